// Golden-image comparison against resources/golden/, failure artefacts and the SPT_UPDATE_GOLDEN rewrite.
#include "golden.hpp"
#include "spt/error.hpp"
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace spt::test {

namespace fs = std::filesystem;

std::string golden_path(const std::string& name) { return std::string(SPT_SOURCE_DIR) + "/resources/golden/" + name + ".png"; }

std::string golden_output_dir() { return std::string(SPT_BINARY_DIR) + "/test-output/golden"; }

bool golden_update_requested() {
    const char* v = std::getenv("SPT_UPDATE_GOLDEN");
    return v && std::string(v) == "1";
}

GoldenOutcome check_golden(const render::Image& image, const std::string& name, bool allow_update,
                           const render::CompareOptions& options) {
    GoldenOutcome out;
    const std::string baseline = golden_path(name);
    if (allow_update && golden_update_requested()) {
        fs::create_directories(fs::path(baseline).parent_path());
        render::write_png(image, baseline);
        out.passed = out.updated = true;
        out.message = "golden image updated: " + baseline;
        return out;
    }
    std::ostringstream msg;
    render::CompareResult r;
    bool have_baseline = fs::exists(baseline);
    if (have_baseline) {
        try {
            r = render::compare_images(image, render::read_png(baseline), options);
        } catch (const Error& e) {
            msg << e.what() << "\n";
            have_baseline = false;
        }
    }
    if (have_baseline && r.passed) {
        out.passed = true;
        return out;
    }
    fs::create_directories(golden_output_dir());
    out.actual_path = golden_output_dir() + "/" + name + ".actual.png";
    render::write_png(image, out.actual_path);
    if (!have_baseline) {
        msg << "no golden image " << baseline << "\n  actual: " << out.actual_path
            << "\n  to accept it: SPT_UPDATE_GOLDEN=1 ctest -R golden, then look at it and commit it";
    } else {
        msg << "image differs from " << baseline << ": " << r.summary() << " (allowed: channel difference "
            << options.channel_threshold << ", " << options.max_differing_fraction * 100.0 << "% of pixels)"
            << "\n  actual: " << out.actual_path;
        if (r.same_size) {
            out.diff_path = golden_output_dir() + "/" + name + ".diff.png";
            render::write_png(r.diff, out.diff_path);
            msg << "\n  diff:   " << out.diff_path << " (differing pixels in red)";
        }
        msg << "\n  if the change is intended: SPT_UPDATE_GOLDEN=1 ctest -R golden, look at the new image, commit it";
    }
    out.message = msg.str();
    return out;
}

} // namespace spt::test
