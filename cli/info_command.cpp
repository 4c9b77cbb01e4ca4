// spt info FILE.spt [--json]
#include "commands.hpp"
#include "spt/compact_tree.hpp"
#include "spt/spt_file.hpp"
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

namespace spt::cli {
namespace {

struct InfoArgs {
    std::string path;
    bool json = false;
};

nlohmann::json describe(const SptDocument& doc, const std::string& path) {
    using nlohmann::json;
    size_t face = 0;
    for (size_t i = 0; i < doc.samples.size(); ++i) face += doc.samples.is_face_sample(i);
    json j;
    j["file"] = path;
    j["bytes"] = std::filesystem::file_size(path);
    j["format_version"] = spt_version_for(doc);
    j["valid"] = true;
    j["mesh"] = {{"name", doc.mesh.name},
                 {"vertices", doc.mesh.vertex_count},
                 {"triangles", doc.mesh.triangle_count},
                 {"hash", doc.mesh.hash},
                 {"diagonal", doc.mesh.diagonal}};
    const Eigen::Vector3d& o = doc.samples.origin;
    j["local_origin"] = {o.x(), o.y(), o.z()};
    j["samples"] = {{"total", doc.samples.size()}, {"vertex", doc.samples.size() - face}, {"face", face}};
    j["trees"] = json::array();
    for (const auto& t : doc.trees) {
        std::vector<float> radii;
        size_t leaves = 0, largest = 0;
        for (const TreeNode* n : t.active_nodes()) {
            ++leaves;
            radii.push_back(n->ss_radius);
            largest = std::max(largest, n->samples.size());
        }
        std::sort(radii.begin(), radii.end());
        const TreeNode* root = t.find(root_id());
        const CompactTree compact(t, doc.samples);
        j["trees"].push_back({{"name", t.name()},
                              {"nodes", t.node_count()},
                              {"active_nodes", leaves},
                              {"depth", t.depth()},
                              {"largest_active_node", largest},
                              {"ss_radius", {{"min", radii.front()}, {"median", radii[radii.size() / 2]}, {"max", radii.back()}}},
                              {"root_bv_radius", root->bv_radius},
                              {"query_layout_bytes", compact.memory_bytes()},
                              {"query_bytes_per_sample", double(compact.memory_bytes()) / double(std::max<size_t>(1, doc.samples.size()))}});
    }
    return j;
}

int run_info(const InfoArgs& a) {
    const SptDocument doc = load_spt(a.path); // throws with the first problem and its offset
    const nlohmann::json j = describe(doc, a.path);
    if (a.json) {
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    std::cout << a.path << ": valid .spt version " << j["format_version"] << ", " << j["bytes"] << " bytes\n"
              << "mesh: " << doc.mesh.name << ", " << doc.mesh.vertex_count << " vertices, " << doc.mesh.triangle_count
              << " triangles, diagonal " << doc.mesh.diagonal << ", local origin " << j["local_origin"].dump() << "\n"
              << "samples: " << j["samples"]["total"] << " (" << j["samples"]["vertex"] << " vertex, "
              << j["samples"]["face"] << " face)\n";
    for (const auto& t : j["trees"])
        std::cout << "tree '" << t["name"].get<std::string>() << "': " << t["nodes"] << " nodes, " << t["active_nodes"]
                  << " active, depth " << t["depth"] << ", largest active node " << t["largest_active_node"]
                  << " samples\n  sampling-sphere radius min " << t["ss_radius"]["min"] << " median "
                  << t["ss_radius"]["median"] << " max " << t["ss_radius"]["max"] << "; root bounding radius "
                  << t["root_bv_radius"] << "\n  query layout " << t["query_layout_bytes"] << " bytes ("
                  << t["query_bytes_per_sample"].get<double>() << " per sample)\n";
    return 0;
}

} // namespace

Action add_info_command(CLI::App& app) {
    auto a = std::make_shared<InfoArgs>();
    CLI::App* c = app.add_subcommand("info", "Describe and validate a .spt file");
    c->add_option("file", a->path, "The .spt file")->required();
    c->add_flag("--json", a->json, "Print JSON instead of text");
    return [a] { return run_info(*a); };
}

} // namespace spt::cli
