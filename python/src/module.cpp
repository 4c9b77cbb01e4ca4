// The Python module `spt`: spt.load, spt.collide, spt.distance, spt.backtrack over core's public
// API (docs/queries.md, "Python"). Arguments are converted here and in pose_array.cpp; the work is
// core's, one batch a call.
#include "model.hpp"
#include "queries.hpp"
#include "spt/error.hpp"
#include "spt/version.hpp"
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <limits>

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

// spt.Error.kind: the error's kind in words, as a caller would test it.
const char* kind_name(spt::ErrorKind kind) {
    switch (kind) {
    case spt::ErrorKind::Usage: return "usage";
    case spt::ErrorKind::BadInput: return "bad input";
    case spt::ErrorKind::CannotWrite: return "cannot write";
    }
    return "bad input";
}

// What a model is at a glance in a session: its file, tree, size and whether `exact` works.
std::string model_repr(const spt::python::Model& m) {
    return "<spt.Model '" + m.path + "' tree '" + m.tree + "', " + std::to_string(m.model.tree().sphere_count()) +
           " spheres" + (m.model.has_mesh() ? ", with triangles>" : ">");
}

} // namespace

PYBIND11_MODULE(spt, m) {
    using namespace spt::python;
    m.doc() = "Collision detection with sampling trees: spt.load models, then spt.collide, spt.distance and "
              "spt.backtrack for many poses of B in A's frame in one call (docs/queries.md, \"Python\").";
    m.attr("__version__") = SPT_VERSION_STRING;

    // spt::Error as spt.Error with the library's message, the CLI's "spt: error: ..." without the
    // prefix, and its kind ("usage", "bad input", "cannot write"), which the CLI maps to exit codes.
    static py::exception<spt::Error> error(m, "Error", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const spt::Error& e) {
            py::object instance = py::reinterpret_borrow<py::object>(error.ptr())(e.what());
            instance.attr("kind") = kind_name(e.kind());
            PyErr_SetObject(error.ptr(), instance.ptr());
        }
    });

    py::class_<Model, std::shared_ptr<Model>>(m, "Model", "An object ready for queries: what spt.load returns.")
        .def_property_readonly("path", [](const Model& s) { return s.path; }, "The file it was loaded from.")
        .def_property_readonly("tree", [](const Model& s) { return s.tree; }, "The name of the tree it uses.")
        .def_property_readonly("has_triangles", [](const Model& s) { return s.model.has_mesh(); },
                               "True when level 'exact' is available (a mesh, or a .spt file with mesh=).")
        .def_property_readonly("diagonal", [](const Model& s) { return s.model.diagonal(); },
                               "Bounding-box diagonal of the mesh, model units.")
        .def_property_readonly("spheres", [](const Model& s) { return s.model.tree().sphere_count(); },
                               "Sampling spheres in the tree.")
        .def("__repr__", &model_repr);

    m.def(
        "load",
        [](const std::string& path, const TreeChoice& tree, const std::optional<std::string>& mesh) {
            return std::make_shared<Model>(load_model(path, tree, mesh.value_or("")));
        },
        "path"_a, "tree"_a = py::none(), "mesh"_a = py::none(),
        "Load an object: a .spt file (tree: its name or index, default the first; mesh: its mesh file, "
        "for level 'exact') or a mesh converted with `spt convert`'s defaults. Raises spt.Error naming the file.");

    m.def(
        "collide",
        [](const Model& a, const Model& b, const py::handle& poses, const std::string& level, bool surfaces,
           bool culling, double cull_angle, int threads) {
            return collide(a, b, poses, {level, surfaces, culling, cull_angle, threads});
        },
        "a"_a, "b"_a, "poses"_a, "level"_a = "spheres", py::kw_only(), "surfaces"_a = false, "culling"_a = false,
        "cull_angle"_a = 60.0, "threads"_a = 0,
        "Whether B at each pose collides with A (A at the identity): a bool array, `spt query`'s collide column.\n"
        "poses: N x 7 (tx ty tz qw qx qy qz, B in A's frame) or N x 4 x 4 rigid transforms. level: 'bounds', "
        "'spheres' or 'exact'. surfaces, culling, cull_angle: as `spt query --surfaces --culling --cull-angle`. "
        "threads: 0 for every core; the answers do not depend on it.");

    m.def("distance", &distance, "a"_a, "b"_a, "poses"_a, "level"_a = "spheres",
          "max_distance"_a = std::numeric_limits<double>::infinity(), py::kw_only(), "relative_error"_a = 0.0,
          "absolute_error"_a = 0.0, "depth"_a = true, "threads"_a = 0, "return_points"_a = false,
          "How far B at each pose is from A: a float64 array, `spt query --mode distance`'s distance column "
          "(negative: minus the deepest overlap; inf: farther than max_distance).\n"
          "relative_error: stop within that share of the smallest gap; absolute_error: within that much of it "
          "(model units). depth=False: overlapping poses give 0 (and NaN points) without the deepest overlap's "
          "walk, as `--no-depth`. return_points: return (distance, "
          "points_a, points_b), the nearest (or deepest) points, N x 3 in A's frame, NaN where inf.");

    m.def(
        "backtrack",
        [](const Model& a, const Model& b, const py::handle& poses, const py::handle& directions,
           const std::string& level, const std::string& rule, double max_distance, bool surfaces, bool culling,
           double cull_angle, int threads) {
            const CollideArgs args{level, surfaces, culling, cull_angle, threads};
            return backtrack(a, b, poses, directions, args, rule, max_distance);
        },
        "a"_a, "b"_a, "poses"_a, "directions"_a, "level"_a = "spheres", py::kw_only(), "rule"_a = "exact",
        "max_distance"_a = std::numeric_limits<double>::infinity(), "surfaces"_a = false, "culling"_a = false,
        "cull_angle"_a = 60.0, "threads"_a = 0,
        "How far B must move back along -direction (N x 3, its motion in A's frame) until it no longer collides "
        "with A: a float64 array, `spt query`'s backtrack column (0 when apart; inf past max_distance).\n"
        "rule: 'exact' or 'paper', as `spt query --backtrack`.");

    m.def(
        "_time_collide_batch",
        [](const Model& a, const Model& b, const py::handle& poses, const std::string& level, int threads) {
            return time_collide_batch(a, b, poses, {level, false, false, 60.0, threads});
        },
        "a"_a, "b"_a, "poses"_a, "level"_a = "spheres", py::kw_only(), "threads"_a = 0,
        "For benchmarks only: seconds that spt.collide's C++ batch (query_batch) takes for these poses, "
        "converted before the clock starts (python/bench_collide.py).");
}
