// Writes the scenes bundled in resources/scenes/ and the meshes and .spt files they use.
// Usage: spt-make-scenes OUT_DIR. Scenes name the bundled meshes as ../meshes/NAME.
#include "exit_code.hpp"
#include "meshgen.hpp"
#include "out_dir_argument.hpp"
#include "spt/convert.hpp"
#include "spt/deforming_model.hpp"
#include "spt/error.hpp"
#include "walk_tree.hpp"
#include <nlohmann/json.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

namespace {

using json = nlohmann::ordered_json;
namespace fs = std::filesystem;
using namespace spt;

// Uniform in [lo, hi) from the raw generator output, identical on every standard library.
double uniform(std::mt19937& rng, double lo, double hi) { return lo + (hi - lo) * (double(rng()) / 4294967296.0); }

// Vectors of uniform draws, one draw a statement, z first: the order of a call's arguments is
// the compiler's choice, and the scenes must come out the same from every build (this is the
// order in which they were first made).
Eigen::Vector3d xyz(std::mt19937& rng, double lo, double hi) {
    const double z = uniform(rng, lo, hi), y = uniform(rng, lo, hi), x = uniform(rng, lo, hi);
    return {x, y, z};
}
Eigen::Vector2d yz(std::mt19937& rng, double lo, double hi) {
    const double z = uniform(rng, lo, hi), y = uniform(rng, lo, hi);
    return {y, z};
}

json vec(double x, double y, double z) { return json::array({x, y, z}); }
json vec3(const Eigen::Vector3d& v) { return vec(v.x(), v.y(), v.z()); }

json object(const std::string& name, const std::string& model) { return json{{"name", name}, {"model", model}}; }

json fixed(const std::string& name, const std::string& model, const json& position) {
    json o = object(name, model);
    o["static"] = true;
    o["position"] = position;
    return o;
}

// One field a line, one object a line: readable, and diffs show which object changed.
void write_scene(const fs::path& dir, const std::string& name, const json& scene) {
    std::ofstream out(dir / name);
    out << "{\n";
    for (auto it = scene.begin(); it != scene.end(); ++it) {
        if (it.key() == "objects") continue;
        out << "  \"" << it.key() << "\": " << it.value().dump() << ",\n";
    }
    out << "  \"objects\": [\n";
    for (size_t i = 0; i < scene["objects"].size(); ++i)
        out << "    " << scene["objects"][i].dump() << (i + 1 < scene["objects"].size() ? ",\n" : "\n");
    out << "  ]\n}\n";
    if (!out) throw Error(ErrorKind::CannotWrite, (dir / name).string() + ": write failed");
}

json header(double dt, int steps, std::initializer_list<const char*> effects) {
    json s;
    s["spt_scene"] = 1;
    s["dt"] = dt;
    s["steps"] = steps;
    s["effects"] = json::array();
    for (const char* e : effects) s["effects"].push_back(e);
    return s;
}

// Paper Fig. 8: two objects given random motion directions towards each other, colliding and moved back.
void fig8(const fs::path& dir) {
    std::mt19937 rng(8);
    json s = header(0.01, 150, {"motion", "contacts", "depth", "pairs", "response"});
    s["response"] = {{"rule", "backtrack"}, {"restitution", 0.5}};
    json a = object("torus", "../meshes/torus.obj"), b = object("part", "../meshes/cad_part.stl");
    a["position"] = vec(-1.5, 0, 0), b["position"] = vec(1.5, 0.1, 0);
    const Eigen::Vector2d ta = yz(rng, -0.3, 0.3);
    const Eigen::Vector3d da = Eigen::Vector3d(1, ta.x(), ta.y()).normalized();
    const Eigen::Vector2d tb = yz(rng, -0.3, 0.3);
    const Eigen::Vector3d db = Eigen::Vector3d(-1, tb.x(), tb.y()).normalized();
    a["velocity"] = vec(2 * da.x(), 2 * da.y(), 2 * da.z());
    b["velocity"] = vec(2 * db.x(), 2 * db.y(), 2 * db.z());
    a["angular_velocity"] = vec3(xyz(rng, -1, 1));
    b["angular_velocity"] = vec3(xyz(rng, -1, 1));
    s["objects"] = {a, b};
    write_scene(dir, "fig8.json", s);
}

// The skinned walking figure walks its clip along a path over the floor, 1 cm into it, so that
// each foot strike is a contact. Its tree "walk" holds the feet as the root's left child, selected
// at the pose where a foot strikes (clip time 1/24 s: the front foot lands), so most walks end
// two levels down.
void walking(const fs::path& dir, const fs::path& models) {
    const fs::path figure = models / "walking_figure.gltf";
    auto mesh = std::make_shared<AnimatedMesh>(import_animated_mesh(figure.string()));
    ConvertOptions options; // faces sampled to 3 cm (1.7% of its height): a small file
    options.tolerance = 0.03;
    SptDocument doc = make_document(mesh->imported.mesh, options);
    DeformingModel strike(doc, mesh);
    strike.pose(&mesh->clips[mesh->find_clip("walk")], 1.0 / 24);
    std::vector<Eigen::Vector3d> at;
    for (const Eigen::Vector3f& p : strike.sample_points()) at.push_back(doc.samples.origin + p.cast<double>());
    doc.trees.clear(); // the walk tree only
    scenegen::add_feet_first_tree(doc, "walk", 0.08, at);
    save_spt(doc, (dir / "figure_walk.spt").string());
    json s = header(0.01, 200, {"motion", "contacts", "depth", "pairs", "deform"});
    json walker = object("walker", "figure_walk.spt");
    walker["mesh"] = "../models/walking_figure.gltf";
    walker["tree"] = "walk";
    walker["animation"] = {{"clip", "walk"}};
    // 1.4 m/s along +z, the way it faces: about the stride its legs take.
    walker["path"] = {{{"t", 0}, {"position", vec(0, -0.01, -1.4)}, {"orientation", {1, 0, 0, 0}}},
                      {{"t", 2}, {"position", vec(0, -0.01, 1.4)}, {"orientation", {1, 0, 0, 0}}}};
    s["objects"] = {fixed("floor", "floor.obj", vec(0, -0.25, 0)), walker};
    write_scene(dir, "walking.json", s);
}

// A thin wall and a fast small ball: 1 unit a step against a wall 0.02 thick.
void thin_wall(const fs::path& dir) {
    json s = header(0.01, 20, {"motion", "contacts", "depth", "ccd"});
    json bullet = object("bullet", "../meshes/sphere.stl");
    bullet["scale"] = 0.1;
    bullet["position"] = vec(-0.7, 0.1, 0.05);
    bullet["velocity"] = vec(100, 0, 0);
    s["objects"] = {fixed("wall", "wall.obj", vec(0, 0, 0)), bullet};
    write_scene(dir, "thin_wall.json", s);
}

// A box dropped on the floor, settling under gravity with the kinematic response. Both sampled
// to a coarse tolerance, so that 10,000 steps of face-on-face contact run in seconds.
void box_settle(const fs::path& dir, const meshgen::RawMesh& floor) {
    ConvertOptions options;
    options.tolerance = 0.03;
    save_spt(make_document(meshgen::prepare(meshgen::box(1, 1, 1, 4), "crate").mesh, options),
             (dir / "crate.spt").string());
    options.tolerance = 0.2; // the floor: 2.5% of its side
    save_spt(make_document(meshgen::prepare(floor, "slab").mesh, options), (dir / "slab.spt").string());
    json s = header(0.01, 10000, {"motion", "gravity", "contacts", "depth", "response"});
    s["response"] = {{"rule", "backtrack"}, {"restitution", 0}};
    json box = object("box", "crate.spt");
    box["position"] = vec(0.1, 0.8, -0.2);
    s["objects"] = {fixed("floor", "slab.spt", vec(0, -0.25, 0)), box};
    write_scene(dir, "box_settle.json", s);
}

// 1,000 small objects on a jittered 10 x 10 x 10 lattice above a floor: the broad phase's scene.
// Their models are sampled at the vertices only (162 spheres each).
void pile(const fs::path& dir) {
    ConvertOptions coarse;
    coarse.auto_tolerance = false;
    save_spt(make_document(meshgen::prepare(meshgen::icosphere(0.4, 2), "pebble").mesh, coarse),
             (dir / "pebble.spt").string());
    // Flat faces would need face samples (a box's vertices alone leave them open), and deep
    // face-on-face overlaps in a heap cost thousands of sphere pairs: pebbles of two sizes.
    save_spt(make_document(meshgen::prepare(meshgen::icosphere(0.3, 2), "grit").mesh, coarse),
             (dir / "grit.spt").string());
    std::mt19937 rng(1000);
    json s = header(0.01, 300, {"motion", "gravity", "contacts", "depth", "response"});
    s["response"] = {{"rule", "backtrack"}, {"restitution", 0.2}};
    json objects = json::array();
    json floor = fixed("floor", "floor.obj", vec(0, -0.5, 0));
    floor["scale"] = 2;
    objects.push_back(floor);
    for (int i = 0; i < 1000; ++i) {
        json o = object("o" + std::to_string(i), i % 3 == 0 ? "grit.spt" : "pebble.spt");
        const double jitter_z = uniform(rng, -0.05, 0.05), jitter_x = uniform(rng, -0.05, 0.05); // z first, as in xyz
        o["position"] = vec(1.0 * (i % 10) - 4.5 + jitter_x, 1.0 * (i / 100) + 0.5, 1.0 * (i / 10 % 10) - 4.5 + jitter_z);
        o["velocity"] = vec3(xyz(rng, -0.5, 0.5));
        objects.push_back(o);
    }
    s["objects"] = objects;
    write_scene(dir, "pile.json", s);
}

// Effect dynamics: the scenes its targets are measured on (docs/scenes.md, "Dynamics").
json dynamics_header(double dt, int steps) { return header(dt, steps, {"motion", "gravity", "contacts", "dynamics"}); }

json quaternion_about_z(double degrees) {
    const double h = 0.5 * degrees * M_PI / 180;
    return json::array({std::cos(h), 0.0, 0.0, std::sin(h)});
}

// A ball of radius 0.5 dropped from 1 above a floor: restitution 0.8, no friction; the first
// rebound's apex is 0.8^2 of the drop.
void bounce(const fs::path& dir) {
    json s = dynamics_header(0.005, 400);
    s["dynamics"] = {{"friction", 0}, {"restitution", 0.8}};
    json ball = object("ball", "../meshes/sphere.stl");
    ball["position"] = vec(0, 1.5, 0);
    s["objects"] = {fixed("floor", "floor.obj", vec(0, -0.25, 0)), ball};
    write_scene(dir, "bounce.json", s);
}

// Two half-unit cubes at rest on a static 20-degree slope, one with friction 0.6 (it holds:
// tan 20 = 0.36), one with 0.2 (it slides at g (sin 20 - 0.2 cos 20)). The slope sets no friction of
// its own, so each cube's applies to its contact.
void slope(const fs::path& dir) {
    const double theta = 20 * M_PI / 180;
    const Eigen::Vector3d along(std::cos(theta), std::sin(theta), 0), up(-std::sin(theta), std::cos(theta), 0);
    meshgen::write_obj(meshgen::box(8, 0.4, 3, 8), (dir / "ramp.obj").string());
    json s = dynamics_header(0.01, 200);
    json ramp = fixed("slope", "ramp.obj", vec(0, 0, 0));
    ramp["orientation"] = quaternion_about_z(20);
    json objects = json::array({ramp});
    const double friction[2] = {0.6, 0.2};
    for (int k = 0; k < 2; ++k) {
        json cube = object(k == 0 ? "holds" : "slides", "../meshes/box.ply");
        cube["scale"] = 0.5;
        cube["position"] = vec3(1.0 * along + (0.2 + 0.25 + 0.001) * up + Eigen::Vector3d(0, 0, k == 0 ? -0.75 : 0.75));
        cube["orientation"] = quaternion_about_z(20);
        cube["friction"] = friction[k];
        objects.push_back(cube);
    }
    s["objects"] = objects;
    write_scene(dir, "slope.json", s);
}

// Five unit cubes stacked on a floor, a millimetre apart.
void stack(const fs::path& dir) {
    json s = dynamics_header(0.01, 500);
    json objects = json::array({fixed("floor", "floor.obj", vec(0, -0.25, 0))});
    for (int k = 0; k < 5; ++k) {
        json cube = object("box" + std::to_string(k), "../meshes/box.ply");
        cube["position"] = vec(0, 0.5 + 1.001 * k + 0.001, 0);
        objects.push_back(cube);
    }
    s["objects"] = objects;
    write_scene(dir, "stack.json", s);
}

// 300 balls of radius 0.1 dropped into an open-topped box (a floor and four walls, 3 x 3 inside).
// The balls are sampled at their vertices only (162 spheres; a contact patch then holds a few
// sphere pairs, not thousands); their mesh beside gives their mass and inertia.
void balls_in_box(const fs::path& dir) {
    const meshgen::RawMesh ball_mesh = meshgen::icosphere(0.1, 2);
    meshgen::write_obj(ball_mesh, (dir / "ball.obj").string());
    ConvertOptions coarse;
    coarse.auto_tolerance = false;
    save_spt(make_document(import_mesh((dir / "ball.obj").string()).mesh, coarse), (dir / "ball.spt").string());
    meshgen::write_obj(meshgen::box(3.4, 1.0, 0.2, 4), (dir / "bin_wall.obj").string());
    std::mt19937 rng(300);
    json s = dynamics_header(0.01, 300);
    json objects = json::array({fixed("floor", "floor.obj", vec(0, -0.25, 0))});
    const double side[4][2] = {{0, -1.6}, {0, 1.6}, {-1.6, 0}, {1.6, 0}};
    for (int k = 0; k < 4; ++k) {
        json wall = fixed("wall" + std::to_string(k), "bin_wall.obj", vec(side[k][0], 0.5, side[k][1]));
        if (k >= 2) wall["orientation"] = json::array({std::sqrt(0.5), 0.0, std::sqrt(0.5), 0.0});
        objects.push_back(wall);
    }
    for (int i = 0; i < 300; ++i) {
        json ball = object("ball" + std::to_string(i), "ball.spt");
        ball["mesh"] = "ball.obj";
        const Eigen::Vector3d jitter = xyz(rng, -0.02, 0.02);
        ball["position"] = vec3(Eigen::Vector3d(0.25 * (i % 10) - 1.125, 0.3 + 0.25 * (i / 100), 0.25 * (i / 10 % 10) - 1.125) + jitter);
        ball["velocity"] = vec3(xyz(rng, -0.5, 0.5));
        objects.push_back(ball);
    }
    s["objects"] = objects;
    write_scene(dir, "balls_in_box.json", s);
}

// The pile (pile.json's objects and velocities) with dynamics: masses for its .spt pebbles
// (their icospheres' volumes at density 1), friction 0.8 and rolling friction 0.2 so that it
// heaps, on a floor wide enough for the heap (24 x 24).
void pile_dynamics(const fs::path& dir) {
    std::ifstream in(dir / "pile.json");
    json s = json::parse(in);
    s["effects"] = json::array({"motion", "gravity", "contacts", "dynamics"});
    s.erase("response");
    s["dynamics"] = {{"friction", 0.8}, {"rolling_friction", 0.2}};
    json& objects = s["objects"];
    objects[0]["scale"] = 3;
    objects[0]["position"] = vec(0, -0.75, 0);
    for (size_t i = 1; i < objects.size(); ++i) {
        const double r = objects[i]["model"] == "grit.spt" ? 0.3 : 0.4;
        objects[i]["mass"] = std::round(4.0 / 3.0 * M_PI * r * r * r * 1000) / 1000; // a sphere's, to 3 decimals
    }
    // The fields in pile.json's order, "dynamics" before the objects.
    json out;
    for (const char* key : {"spt_scene", "dt", "steps", "effects", "dynamics", "objects"}) out[key] = s[key];
    write_scene(dir, "pile_dynamics.json", out);
}

// A robot-like arm (a mount, an upper arm, a forearm and a two-finger gripper, one rigid mesh)
// reaching into a bin four times: down past the rim, the fingertips 1 cm into the bin's floor,
// brushing a wall, up and over to the next place: the third motion of docs/editor.md's targets.
void robot_arm(const fs::path& dir) {
    meshgen::RawMesh arm;
    arm.append(meshgen::cylinder(0.06, 0.5, 24), Eigen::Vector3d(0, 0.8, 0)); // the mount, above the upper arm
    arm.append(meshgen::box(0.7, 0.1, 0.1, 6), Eigen::Vector3d(0.35, 0.5, 0));      // upper arm, from the column's top
    arm.append(meshgen::box(0.08, 0.6, 0.08, 6), Eigen::Vector3d(0.7, 0.2, 0));     // forearm, down
    arm.append(meshgen::box(0.16, 0.04, 0.1, 4), Eigen::Vector3d(0.7, -0.12, 0));   // palm
    arm.append(meshgen::box(0.03, 0.16, 0.08, 4), Eigen::Vector3d(0.64, -0.22, 0)); // fingers
    arm.append(meshgen::box(0.03, 0.16, 0.08, 4), Eigen::Vector3d(0.76, -0.22, 0));
    meshgen::write_obj(arm, (dir / "arm.obj").string());
    meshgen::write_obj(meshgen::box(1.2, 0.1, 1.2, 8), (dir / "bin_floor.obj").string());
    meshgen::write_obj(meshgen::box(1.2, 0.5, 0.05, 6), (dir / "bin_side.obj").string());
    json s = header(0.01, 400, {"motion", "contacts"});
    json objects = json::array({fixed("bin_floor", "bin_floor.obj", vec(0, 0, 0))});
    const double side[4][2] = {{0, -0.625}, {0, 0.625}, {-0.625, 0}, {0.625, 0}};
    for (int k = 0; k < 4; ++k) {
        json wall = fixed("bin_side" + std::to_string(k), "bin_side.obj", vec(side[k][0], 0.3, side[k][1]));
        if (k >= 2) wall["orientation"] = json::array({std::sqrt(0.5), 0.0, std::sqrt(0.5), 0.0});
        objects.push_back(wall);
    }
    // The arm's fingertips are 0.3 below its origin and 0.7 out along x: the origin sits above the
    // place it reaches for, minus that offset, turned about y between reaches.
    json arm_object = object("arm", "arm.obj");
    json path = json::array();
    const double reach[4][2] = {{-0.3, -0.3}, {0.3, -0.25}, {0.25, 0.3}, {-0.35, 0.2}};
    double t = 0;
    for (int k = 0; k < 4; ++k) {
        const double angle = 0.3 * k;
        const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()));
        const Eigen::Vector3d tip = q * Eigen::Vector3d(0.7, -0.3, 0);
        const Eigen::Vector3d above(reach[k][0] - tip.x(), 1.0, reach[k][1] - tip.z());
        const Eigen::Vector3d down(above.x(), 0.05 + 0.3 - 0.01, above.z()); // tips 1 cm into the floor's top (y 0.05)
        const json orientation = json::array({q.w(), q.x(), q.y(), q.z()});
        path.push_back({{"t", t}, {"position", vec3(above)}, {"orientation", orientation}});
        path.push_back({{"t", t + 0.4}, {"position", vec3(down)}, {"orientation", orientation}});
        path.push_back({{"t", t + 0.6}, {"position", vec3(down + Eigen::Vector3d(0.05, 0, 0.05))}, {"orientation", orientation}});
        path.push_back({{"t", t + 0.85}, {"position", vec3(above)}, {"orientation", orientation}});
        t += 1.0;
    }
    arm_object["path"] = path;
    objects.push_back(arm_object);
    s["objects"] = objects;
    write_scene(dir, "robot_arm.json", s);
}

} // namespace

int main(int argc, char** argv) {
    if (int code = 0; !spt::meshgen::out_dir_argument(argc, argv, "usage: spt-make-scenes OUT_DIR", code)) return code;
    const fs::path dir = argv[1];
    try {
        fs::create_directories(dir);
        const fs::path meshes = std::string(SPT_MESHES_DIR);
        const meshgen::RawMesh floor = meshgen::box(8, 0.5, 8, 8);
        meshgen::write_obj(floor, (dir / "floor.obj").string());
        meshgen::write_obj(meshgen::box(0.02, 2, 2, 8), (dir / "wall.obj").string());
        fig8(dir);
        walking(dir, meshes.parent_path() / "models");
        thin_wall(dir);
        box_settle(dir, floor);
        pile(dir);
        bounce(dir);
        slope(dir);
        stack(dir);
        balls_in_box(dir);
        pile_dynamics(dir);
        robot_arm(dir);
    } catch (const Error& e) {
        std::cerr << e.what() << "\n";
        return spt::cli::exit_code(e.kind());
    }
    return 0;
}
