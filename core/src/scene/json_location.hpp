#pragma once
// Where a JSON text stops being valid: line, column and the JSON path being read there.
#include <string>

namespace spt::detail {

/// Empty if `text` is valid JSON; otherwise "line L, column C, at /json/path: reason".
std::string json_syntax_problem(const std::string& text);

} // namespace spt::detail
