// Plot CSV: one row a plotted point (mesh, kind, configuration, median time, agreement), RFC 4180 quoting.
#include "plot_csv.hpp"
#include "spt/error.hpp"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace bench {
namespace {

const std::pair<PointKind, const char*> kKindNames[] = {
    {PointKind::Bounds, "bounds"}, {PointKind::Spheres, "spheres"}, {PointKind::Exact, "exact"},
    {PointKind::Fcl, "fcl"},       {PointKind::Bullet, "bullet"},   {PointKind::BruteForce, "brute_force"}};

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string number(double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%.10g", v);
    return b;
}

// Splits one CSV line; false if a quoted field is not closed or a quote is followed by text.
bool split(const std::string& line, std::vector<std::string>& fields) {
    fields.assign(1, "");
    bool in_quotes = false, was_quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (in_quotes) {
            if (c != '"') fields.back() += c;
            else if (i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
            else in_quotes = false, was_quoted = true;
        } else if (c == ',') fields.emplace_back(), was_quoted = false;
        else if (c == '"' && fields.back().empty() && !was_quoted) in_quotes = true;
        else if (was_quoted) return false;
        else fields.back() += c;
    }
    return !in_quotes;
}

double parse_number(const std::string& s, bool& ok) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    ok = !s.empty() && end == s.c_str() + s.size() && std::isfinite(v);
    return v;
}

} // namespace

bool write_plot_csv(const std::string& path, const PlotData& data, std::string& error) {
    std::ofstream f(path, std::ios::binary);
    f << kPlotCsvHeader << "\n";
    for (const PlotPoint& p : data.points) {
        const char* kind = "";
        for (const auto& [k, name] : kKindNames)
            if (k == p.kind) kind = name;
        f << quoted(data.mesh) << "," << kind << "," << quoted(p.name) << "," << number(p.ns) << "," << number(p.agreement) << "\n";
    }
    f.close();
    if (f) return true;
    error = path + ": cannot write";
    return false;
}

PlotData read_plot_csv(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) spt::throw_bad_input(path, "cannot open");
    PlotData data;
    std::string line;
    std::vector<std::string> cells;
    int n = 0;
    while (std::getline(f, line)) {
        ++n;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::string at = "line " + std::to_string(n) + ": ";
        if (n == 1) {
            if (line != kPlotCsvHeader) spt::throw_bad_input(path, at + "header is not '" + std::string(kPlotCsvHeader) + "'");
            continue;
        }
        if (line.empty()) continue;
        if (!split(line, cells)) spt::throw_bad_input(path, at + "unbalanced quotes");
        if (cells.size() != 5)
            spt::throw_bad_input(path, at + "expected 5 fields, found " + std::to_string(cells.size()));
        if (cells[0].empty()) spt::throw_bad_input(path, at + "empty mesh name");
        if (data.mesh.empty()) data.mesh = cells[0];
        else if (cells[0] != data.mesh)
            spt::throw_bad_input(path, at + "mesh '" + cells[0] + "' differs from '" + data.mesh + "' above");
        PlotPoint p;
        bool known = false;
        for (const auto& [k, name] : kKindNames)
            if (cells[1] == name) p.kind = k, known = true;
        if (!known)
            spt::throw_bad_input(path, at + "unknown kind '" + cells[1] + "' (bounds, spheres, exact, fcl, bullet, brute_force)");
        p.name = cells[2];
        bool ok = false;
        p.ns = parse_number(cells[3], ok);
        if (!ok || p.ns < 0) spt::throw_bad_input(path, at + "median_time_ns '" + cells[3] + "' is not a time in nanoseconds");
        p.agreement = parse_number(cells[4], ok);
        if (!ok || p.agreement < 0 || p.agreement > 100)
            spt::throw_bad_input(path, at + "agree_near_percent '" + cells[4] + "' is not a percentage");
        data.points.push_back(std::move(p));
    }
    if (n == 0) spt::throw_bad_input(path, "empty file (expected the header '" + std::string(kPlotCsvHeader) + "')");
    if (data.points.empty()) spt::throw_bad_input(path, "no points");
    return data;
}

} // namespace bench
