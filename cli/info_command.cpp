// spt info FILE.spt|MODEL [--json]: a .spt file validated and described, or a mesh with its clips.
#include "commands.hpp"
#include "spt/animation.hpp"
#include "spt/compact_tree.hpp"
#include "spt/spt_file.hpp"
#include <algorithm>
#include <cctype>
#include <cstdio>
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
        json& tj = j["trees"].back();
        tj["recipe_steps"] = t.recipe().size();
        tj["motion_builds"] = json::array();
        for (const MotionBuildStep& m : t.motion_builds())
            tj["motion_builds"].push_back({{"node", m.node}, {"scene", m.scene}, {"object", m.object}, {"steps", m.steps},
                                           {"leaf_size", m.leaf_size}});
    }
    return j;
}

// A mesh file: what import makes of it, and its animation clips.
nlohmann::json describe_model(const AnimatedMesh& m, const std::string& path) {
    using nlohmann::json;
    const ImportReport& r = m.imported.report;
    json j;
    j["file"] = path;
    j["mesh"] = {{"name", m.imported.mesh.name},
                 {"vertices", m.imported.mesh.positions.size()},
                 {"triangles", m.imported.mesh.triangles.size()},
                 {"closed", r.closed},
                 {"diagonal", m.imported.mesh.diagonal()}};
    j["skinned"] = m.rig.skinned;
    j["joints"] = m.rig.joint_count;
    j["morph_targets"] = m.rig.morph_targets.size();
    j["clips"] = json::array();
    for (size_t i = 0; i < m.clips.size(); ++i) {
        const ClipStretch st = measure_stretch(m, m.clips[i]);
        j["clips"].push_back({{"index", i},
                              {"name", m.clips[i].name},
                              {"duration", m.clips[i].duration},
                              {"joints", m.clips[i].joints_animated},
                              {"stretch",
                               {{"largest", st.largest},
                                {"smallest", st.smallest},
                                {"time", st.time},
                                {"where", {st.where.x(), st.where.y(), st.where.z()}},
                                {"joint", st.joint},
                                {"gap_factor", st.gap_factor()}}}});
    }
    j["warnings"] = r.warnings;
    return j;
}

int run_model_info(const InfoArgs& a) {
    const AnimatedMesh m = import_animated_mesh(a.path); // throws naming the file and the problem
    const nlohmann::json j = describe_model(m, a.path);
    if (a.json) {
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    std::cout << a.path << ": mesh, " << j["mesh"]["vertices"] << " vertices, " << j["mesh"]["triangles"]
              << " triangles, " << (m.imported.report.closed ? "closed" : "open") << ", diagonal "
              << m.imported.mesh.diagonal() << "\n";
    if (m.rig.skinned || !m.rig.morph_targets.empty())
        std::cout << "skin: " << m.rig.joint_count << " joints, " << m.rig.morph_targets.size() << " morph targets\n";
    std::cout << "clips: " << m.clips.size() << "\n";
    if (!m.clips.empty()) std::cout << "  index  duration_s  joints  name\n";
    for (size_t i = 0; i < m.clips.size(); ++i) {
        char line[64];
        std::snprintf(line, sizeof line, "  %5zu  %10.4f  %6u  ", i, m.clips[i].duration, m.clips[i].joints_animated);
        std::cout << line << m.clips[i].name << "\n";
    }
    for (const auto& c : j["clips"]) {
        const auto& st = c["stretch"];
        char line[256];
        std::snprintf(line, sizeof line, "  stretch of clip %d: largest %.3f at %.3f s, near (%.4g, %.4g, %.4g)",
                      c["index"].get<int>(), st["largest"].get<double>(), st["time"].get<double>(),
                      st["where"][0].get<double>(), st["where"][1].get<double>(), st["where"][2].get<double>());
        std::cout << line << (st["joint"].get<std::string>().empty() ? "" : " on joint '" + st["joint"].get<std::string>() + "'");
        std::snprintf(line, sizeof line, "; coverage gaps there up to %.3gx the bind pose's\n", st["gap_factor"].get<double>());
        std::cout << line;
    }
    for (const std::string& w : m.imported.report.warnings) std::cout << "warning: " << w << "\n";
    return 0;
}

// Whether `path` names a .spt file (by its extension, any case); anything else is read as a mesh.
bool is_spt(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".spt";
}

int run_info(const InfoArgs& a) {
    if (!is_spt(a.path)) return run_model_info(a);
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
    for (const auto& t : j["trees"]) {
        std::cout << "tree '" << t["name"].get<std::string>() << "': " << t["nodes"] << " nodes, " << t["active_nodes"]
                  << " active, depth " << t["depth"] << ", largest active node " << t["largest_active_node"]
                  << " samples\n  sampling-sphere radius min " << t["ss_radius"]["min"] << " median "
                  << t["ss_radius"]["median"] << " max " << t["ss_radius"]["max"] << "; root bounding radius "
                  << t["root_bv_radius"] << "\n  query layout " << t["query_layout_bytes"] << " bytes ("
                  << t["query_bytes_per_sample"].get<double>() << " per sample)\n";
        for (const auto& m : t["motion_builds"])
            std::cout << "  built for a motion under node " << m["node"] << ": object '" << m["object"].get<std::string>()
                      << "' of " << m["scene"].get<std::string>() << "\n";
    }
    return 0;
}

} // namespace

Action add_info_command(CLI::App& app) {
    auto a = std::make_shared<InfoArgs>();
    CLI::App* c = app.add_subcommand("info", "Describe and validate a .spt file, or list a mesh's animation clips");
    c->add_option("file", a->path, "The .spt file, or a mesh file (its clips are listed)")->required();
    c->add_flag("--json", a->json, "Print JSON instead of text");
    return [a] { return run_info(*a); };
}

} // namespace spt::cli
