// Writes the meshes bundled in resources/meshes/. Usage: spt-make-resources OUT_DIR [--big]
// --big also writes torus_1m.ply (1,000,000 vertices) and the same torus as an unindexed
// binary STL, torus_1m.stl (6,000,000 corners to weld), for the conversion benchmark; they are
// not bundled.
#include "exit_code.hpp"
#include "meshgen.hpp"
#include "out_dir_argument.hpp"
#include "spt/error.hpp"
#include <filesystem>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
    const char* usage = "usage: spt-make-resources OUT_DIR [--big]";
    if (int code = 0; !spt::meshgen::out_dir_argument(argc, argv, usage, code, 1)) return code;
    const bool big = argc == 3 && std::string(argv[2]) == "--big";
    if (argc == 3 && !big) {
        std::cerr << usage << '\n';
        return 1;
    }
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    using namespace spt::meshgen;
    try {
        write_obj(figure(), (dir / "figure.obj").string());
        write_obj(torus(0.6, 0.25, 48, 24), (dir / "torus.obj").string());
        write_ply(box(1, 1, 1, 4), (dir / "box.ply").string());
        write_stl(cad_part(), (dir / "cad_part.stl").string());
        write_stl(icosphere(0.5, 3), (dir / "sphere.stl").string());
        if (big) {
            const RawMesh t = torus(1.0, 0.35, 1000, 1000);
            write_ply(t, (dir / "torus_1m.ply").string());
            write_stl(t, (dir / "torus_1m.stl").string());
        }
    } catch (const spt::Error& e) {
        std::cerr << e.what() << "\n";
        return spt::cli::exit_code(e.kind());
    }
    return 0;
}
