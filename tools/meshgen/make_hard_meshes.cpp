// Writes the open, non-manifold and thin meshes of the hard-case suite (core's
// mesh/hard_shapes) as OBJ, for the pair benchmark. Usage: spt-make-hard-meshes OUT_DIR
#include "exit_code.hpp"
#include "meshgen.hpp"
#include "out_dir_argument.hpp"
#include "mesh/hard_shapes.hpp"
#include "mesh/shapes.hpp"
#include "spt/error.hpp"
#include <filesystem>
#include <iostream>

namespace {

void write(const spt::TriangleMesh& m, const std::filesystem::path& path) {
    spt::meshgen::RawMesh raw;
    raw.positions = m.positions;
    raw.triangles = m.triangles;
    spt::meshgen::write_obj(raw, path.string());
}

} // namespace

int main(int argc, char** argv) {
    if (int code = 0; !spt::meshgen::out_dir_argument(argc, argv, "usage: spt-make-hard-meshes OUT_DIR", code)) return code;
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    try {
        write(spt::make_open_box({1, 1, 0.6}, 8), dir / "open_box.obj");
        write(spt::make_open_tube(0.03, 1.2, 16), dir / "open_tube.obj");
        write(spt::make_sheet(1.5, 12), dir / "open_sheet.obj");
        write(spt::make_fan(6), dir / "fan.obj");
        write(spt::make_triangle_soup(300, 0.15, 3), dir / "soup.obj");
        write(spt::make_gapped_box(0.5, 0.02), dir / "gapped_box.obj");
        write(spt::make_plate_with_fin(), dir / "plate_with_fin.obj");
    } catch (const spt::Error& e) {
        std::cerr << e.what() << "\n";
        return spt::cli::exit_code(e.kind());
    }
    return 0;
}
