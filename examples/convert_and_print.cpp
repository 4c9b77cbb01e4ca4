// Example: convert a mesh to a sampling tree and print the tree (paper ids, samples,
// radii), using only the installed public API. Usage: convert_and_print MESH [OUT.spt]
#include <spt/spt.hpp>
#include <cstdio>
#include <string>

namespace {

void print_subtree(const spt::SamplingTree& tree, spt::NodeId id, int max_depth) {
    const spt::TreeNode* n = tree.find(id);
    if (!n) return;
    const int depth = spt::node_depth(id);
    if (depth > max_depth) return;
    std::printf("%*s%llu  %s  bounding r=%.4g  sampling r=%.4g%s\n", 2 * depth, "", (unsigned long long)id,
                n->active ? "active" : "inner ", n->bv_radius, n->ss_radius,
                n->active ? ("  samples=" + std::to_string(n->samples.size())).c_str() : "");
    if (n->active) return;
    print_subtree(tree, spt::left_child(id), max_depth);
    print_subtree(tree, spt::right_child(id), max_depth);
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: %s MESH [OUT.spt]\n", argv[0]);
        return 1;
    }
    try {
        const spt::ImportedMesh imported = spt::import_mesh(argv[1]);
        const spt::ImportReport& r = imported.report;
        std::printf("%s: %zu vertices, %zu faces, %s\n", imported.mesh.name.c_str(), r.vertices, r.faces,
                    r.closed ? "closed" : "open");
        for (const std::string& w : r.warnings) std::printf("  warning: %s\n", w.c_str());

        spt::ConvertStats stats;
        const spt::SptDocument doc = spt::make_document(imported.mesh, {}, &stats);
        const spt::SamplingTree& tree = doc.trees.front();
        std::printf("%zu samples (%zu on vertices, %zu on faces); tree '%s': %zu nodes, depth %d\n",
                    doc.samples.size(), stats.vertex_samples, stats.face_samples, tree.name().c_str(),
                    tree.node_count(), tree.depth());
        std::printf("top of the tree (model units):\n");
        print_subtree(tree, spt::root_id(), 3);

        if (argc == 3) {
            spt::save_spt(doc, argv[2]);
            std::printf("wrote %s\n", argv[2]);
        }
        return 0;
    } catch (const spt::Error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return e.kind() == spt::ErrorKind::BadInput ? 2 : 1; // this program's exit codes
    }
}
