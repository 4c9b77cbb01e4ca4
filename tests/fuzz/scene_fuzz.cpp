// Fuzz target: the scene parser (spt/scene.hpp) on any text, then a few steps of every
// accepted scene with a small box for each model. An accepted scene must hold what the
// schema promises (positive finite dt, finite vectors, unit orientations, unique names,
// keyframes in increasing time), and its simulation must keep every pose finite or refuse
// with Error(BadInput). Hangs show as libFuzzer timeouts.
#include "fuzz_support.hpp"
#include "spt/convert.hpp"
#include "spt/scene.hpp"
#include "spt/simulation.hpp"
#include "spt/spt_file.hpp"
#include "mesh/shapes.hpp"
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <unistd.h>

namespace {

using namespace spt;

// A small box as a .spt file, written once and removed at exit; every object's model is
// replaced by it.
struct BoxModel {
    std::string path =
        (std::filesystem::temp_directory_path() / ("spt-scene-fuzz-" + std::to_string(::getpid()) + ".spt")).string();
    BoxModel() {
        const TriangleMesh box = make_box(Eigen::Vector3d(0.5, 0.25, 0.5), 1);
        ConvertOptions o;
        o.tolerance = 0.1;
        save_spt(make_document(box, o), path);
    }
    ~BoxModel() {
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
    }
};

const std::string& box_model() {
    static const BoxModel model;
    return model.path;
}

bool finite(const Pose& p) { return p.translation.allFinite() && p.rotation.coeffs().allFinite(); }

void check_accepted(const Scene& s) {
    if (!(s.dt > 0) || !std::isfinite(s.dt)) fuzz::fail("accepted a dt that is not positive and finite");
    if (s.steps < 0) fuzz::fail("accepted negative steps");
    if (!s.gravity.allFinite()) fuzz::fail("accepted a non-finite gravity");
    std::set<std::string> names;
    for (const SceneObject& o : s.objects) {
        if (!names.insert(o.name).second) fuzz::fail("accepted two objects of one name");
        if (!finite(o.pose) || !(std::abs(o.pose.rotation.norm() - 1) < 1e-9))
            fuzz::fail("accepted a pose that is not finite or not a unit rotation");
        if (!o.velocity.allFinite() || !o.angular_velocity.allFinite()) fuzz::fail("accepted a non-finite velocity");
        if (!(o.scale > 0) || !std::isfinite(o.scale)) fuzz::fail("accepted a scale that is not positive and finite");
        for (size_t k = 0; k < o.path.size(); ++k) {
            if (!std::isfinite(o.path[k].t) || (k > 0 && !(o.path[k].t > o.path[k - 1].t)))
                fuzz::fail("accepted keyframes not in increasing finite time");
            if (!o.path[k].position.allFinite() || !(std::abs(o.path[k].orientation.norm() - 1) < 1e-9))
                fuzz::fail("accepted a keyframe that is not finite or not a unit rotation");
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    fuzz::expect_bad_input_only([&] {
        Scene s = parse_scene(text, "fuzz.json", "/nonexistent");
        check_accepted(s);
        if (s.objects.size() > 64) return; // the parser is what is fuzzed past this size
        for (SceneObject& o : s.objects) o.model_path = box_model(), o.tree.clear(), o.scale = 1;
        load_models(s);
        Simulation sim(s, s.effects);
        for (int k = 0; k < std::min(s.steps, 4); ++k) {
            sim.step();
            for (const Pose& p : sim.poses())
                if (!finite(p)) fuzz::fail("a step of an accepted scene made a pose that is not finite");
        }
    });
    return 0;
}
