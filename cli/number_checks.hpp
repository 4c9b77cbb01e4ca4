#pragma once
// CLI11 checks for numeric options. CLI::Range lets NaN through (every comparison with it is
// false) and prints infinite bounds digit by digit; these name the option's range in words.
#include <CLI/CLI.hpp>
#include <cmath>
#include <sstream>
#include <string>

namespace spt::cli {

/// True if `v` is one whole finite number (stream syntax: "nan", "inf" and overflow fail), stored in `d`.
inline bool parse_finite(const std::string& v, double& d) {
    std::istringstream in(v);
    return in >> d && (in >> std::ws).eof() && std::isfinite(d);
}

/// A finite number in [lo, hi]; `range` says so in the message (e.g. "from 0 to 1").
inline CLI::Validator finite_in(double lo, double hi, const std::string& range) {
    return CLI::Validator(
        [lo, hi, range](std::string& v) -> std::string {
            double d = 0;
            if (parse_finite(v, d) && d >= lo && d <= hi) return {};
            return "must be a finite number " + range + ", not '" + v + "'";
        },
        "NUMBER");
}

/// A finite number above zero.
inline CLI::Validator finite_positive() {
    return CLI::Validator(
        [](std::string& v) -> std::string {
            double d = 0;
            if (parse_finite(v, d) && d > 0) return {};
            return "must be a finite positive number, not '" + v + "'";
        },
        "POSITIVE");
}

} // namespace spt::cli
