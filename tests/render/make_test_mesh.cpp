// spt_make_test_mesh KIND OUT [N]: writes a test mesh, binary PLY if OUT ends in .ply,
// else OBJ. KIND is figure (the box figure) or torus: 2N x N vertices, 4 N^2 triangles
// (N = 158: 99,856 triangles).
#include "test_meshes.hpp"
#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: spt_make_test_mesh torus|figure OUT.obj|OUT.ply [N]\n";
        return 1;
    }
    const std::string kind = argv[1], out = argv[2];
    try {
        const bool ply = out.size() > 4 && out.compare(out.size() - 4, 4, ".ply") == 0;
        auto write = [&](const spt::TriangleMesh& m) { ply ? spt::test::write_ply(m, out) : spt::test::write_obj(m, out); };
        if (kind == "torus") {
            const int n = argc > 3 ? std::atoi(argv[3]) : 24;
            if (n < 3 || n > 4000) {
                std::cerr << "N must be 3 to 4000\n";
                return 1;
            }
            write(spt::test::torus(1.0, 0.35, 2 * n, n));
        } else if (kind == "figure") {
            write(spt::test::box_figure());
        } else {
            std::cerr << "unknown mesh kind " << kind << "\n";
            return 1;
        }
    } catch (const std::exception& e) {
        std::cerr << e.what() << "\n";
        return 2;
    }
    return 0;
}
