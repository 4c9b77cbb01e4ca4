// The levels' names, one spelling for the command line, scenes, Python and the benchmarks.
#include "spt/query.hpp"

namespace spt {

std::optional<QueryLevel> query_level_named(std::string_view name) {
    if (name == "bounds") return QueryLevel::Bounds;
    if (name == "spheres") return QueryLevel::Spheres;
    if (name == "exact") return QueryLevel::Exact;
    return std::nullopt;
}

const char* query_level_name(QueryLevel level) {
    switch (level) {
    case QueryLevel::Bounds: return "bounds";
    case QueryLevel::Spheres: return "spheres";
    case QueryLevel::Exact: return "exact";
    }
    return "unknown";
}

} // namespace spt
