// Pose files: one pose a line, tx ty tz qw qx qy qz [dx dy dz].
#include "spt/pose_file.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace spt {

std::vector<PoseLine> read_pose_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw_bad_input(path, "cannot open the pose file");
    return parse_poses(in, path);
}

std::vector<PoseLine> parse_poses(std::istream& in, const std::string& path) {
    std::vector<PoseLine> out;
    std::string text;
    for (size_t line = 1; std::getline(in, text); ++line) {
        // A file saved by an editor that marks UTF-8, or exported from a spreadsheet: the mark is
        // skipped and commas separate as spaces do.
        if (line == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
        std::replace(text.begin(), text.end(), ',', ' ');
        const size_t first = text.find_first_not_of(" \t\r");
        if (first == std::string::npos || text[first] == '#') continue;
        std::istringstream s(text);
        std::vector<double> v;
        std::vector<std::string> tokens; // as written, for messages
        std::string tok;
        auto fail = [&](const std::string& why) {
            throw Error(ErrorKind::BadInput, path + ":" + std::to_string(line) + ": " + why);
        };
        while (s >> tok) {
            char* end = nullptr;
            const double x = std::strtod(tok.c_str(), &end);
            if (end == tok.c_str() || *end != '\0') fail("'" + tok + "' is not a number");
            if (!std::isfinite(x)) fail("'" + tok + "' is not finite");
            v.push_back(x);
            tokens.push_back(tok);
        }
        if (v.size() != 7 && v.size() != 10)
            fail("expected 7 or 10 numbers (tx ty tz qw qx qy qz [dx dy dz]), found " + std::to_string(v.size()));
        for (int k = 0; k < 3; ++k)
            if (std::abs(v[size_t(k)]) > kMaxCoordinate)
                fail("translation " + std::string(1, "xyz"[k]) + " = " + tokens[size_t(k)] +
                     " is beyond 1e16 in magnitude (docs/queries.md, \"Extreme values\")");
        const Eigen::Quaterniond q(v[3], v[4], v[5], v[6]);
        if (q.coeffs().cwiseAbs().maxCoeff() == 0) fail("the quaternion (qw qx qy qz) is zero");
        PoseLine pl;
        pl.pose = Pose::from(Eigen::Vector3d(v[0], v[1], v[2]), q);
        if (v.size() == 10) pl.direction = Eigen::Vector3d(v[7], v[8], v[9]);
        pl.line = line;
        out.push_back(pl);
    }
    return out;
}

void write_pose_file(const std::string& path, const std::vector<Pose>& poses, const std::string& comment) {
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f) throw Error(ErrorKind::CannotWrite, path + ": cannot write the pose file");
    bool ok = comment.empty() || std::fprintf(f, "# %s\n", comment.c_str()) > 0;
    for (const Pose& p : poses)
        ok = ok && std::fprintf(f, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", p.translation.x(), p.translation.y(),
                                p.translation.z(), p.rotation.w(), p.rotation.x(), p.rotation.y(), p.rotation.z()) > 0;
    if (std::fclose(f) != 0 || !ok) throw Error(ErrorKind::CannotWrite, path + ": writing the pose file failed");
}

} // namespace spt
