// Scene JSON to spt::Scene: every field checked, every problem named by file and JSON path.
#include "scene/json_location.hpp"
#include "spt/error.hpp"
#include "spt/scene.hpp"
#include <nlohmann/json.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace spt {
namespace {

using json = nlohmann::json;

class Reader {
public:
    explicit Reader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
        throw Error(ErrorKind::BadInput, file_ + ": at " + (path.empty() ? "/" : path) + ": " + problem);
    }
    void fields(const json& j, const std::string& path, std::initializer_list<const char*> allowed) const {
        if (!j.is_object()) fail(path, "must be an object");
        for (auto it = j.begin(); it != j.end(); ++it) {
            bool ok = false;
            std::string list;
            for (const char* a : allowed) ok |= it.key() == a, list += (list.empty() ? "" : ", ") + std::string(a);
            if (!ok) fail(path + "/" + it.key(), "unknown field '" + it.key() + "' (allowed here: " + list + ")");
        }
    }
    double number(const json& j, const std::string& path) const {
        if (!j.is_number()) fail(path, "must be a number, not " + std::string(j.type_name()));
        const double v = j.get<double>();
        if (!std::isfinite(v)) fail(path, "must be finite");
        return v;
    }
    // A number from lo to hi, both included; else "must be " + range.
    double number_in(const json& j, const std::string& path, double lo, double hi, const char* range) const {
        const double v = number(j, path);
        if (!(v >= lo && v <= hi)) fail(path, std::string("must be ") + range);
        return v;
    }
    Eigen::Vector3d vec3(const json& j, const std::string& path) const {
        if (!j.is_array() || j.size() != 3) fail(path, "must be an array of 3 numbers");
        return {number(j[0], path + "/0"), number(j[1], path + "/1"), number(j[2], path + "/2")};
    }
    Eigen::Quaterniond quat(const json& j, const std::string& path) const {
        if (!j.is_array() || j.size() != 4) fail(path, "must be a quaternion [w, x, y, z]");
        const Eigen::Quaterniond q(number(j[0], path + "/0"), number(j[1], path + "/1"), number(j[2], path + "/2"),
                                   number(j[3], path + "/3"));
        if (!(q.norm() > 1e-9)) fail(path, "quaternion has zero length");
        return q.normalized();
    }
    std::string text(const json& j, const std::string& path) const {
        if (!j.is_string()) fail(path, "must be a string");
        return j.get<std::string>();
    }
    bool flag(const json& j, const std::string& path) const {
        if (!j.is_boolean()) fail(path, "must be true or false");
        return j.get<bool>();
    }

private:
    std::string file_;
};

// How a contact of the object (or, top-level, any pair) behaves under effect dynamics: the fields
// of `j` that are there, written over the three values.
void read_contact_settings(const Reader& r, const json& j, const std::string& p, double& friction, double& restitution,
                           double& rolling_friction) {
    if (j.contains("friction")) friction = r.number_in(j["friction"], p + "/friction", 0, 1e3, "from 0 to 1000");
    if (j.contains("restitution"))
        restitution = r.number_in(j["restitution"], p + "/restitution", 0, 1, "between 0 and 1");
    if (j.contains("rolling_friction"))
        rolling_friction = r.number_in(j["rolling_friction"], p + "/rolling_friction", 0, 1e3, "from 0 to 1000");
}

std::vector<Keyframe> read_path(const Reader& r, const json& j, const std::string& path) {
    if (!j.is_array() || j.empty()) r.fail(path, "must be a non-empty array of keyframes");
    std::vector<Keyframe> keys;
    for (size_t i = 0; i < j.size(); ++i) {
        const std::string p = path + "/" + std::to_string(i);
        r.fields(j[i], p, {"t", "position", "orientation"});
        Keyframe k;
        if (!j[i].contains("t")) r.fail(p, "keyframe needs 't'");
        k.t = r.number(j[i]["t"], p + "/t");
        if (!keys.empty() && !(k.t > keys.back().t)) r.fail(p + "/t", "keyframe times must increase");
        if (j[i].contains("position")) k.position = r.vec3(j[i]["position"], p + "/position");
        if (j[i].contains("orientation")) k.orientation = r.quat(j[i]["orientation"], p + "/orientation");
        keys.push_back(k);
    }
    return keys;
}

AnimationSettings read_animation(const Reader& r, const json& j, const std::string& p) {
    r.fields(j, p, {"clip", "speed", "offset", "loop"});
    AnimationSettings a;
    if (j.contains("clip")) {
        const json& c = j["clip"];
        if (c.is_number_integer() && c.get<int64_t>() >= 0) a.clip = std::to_string(c.get<int64_t>());
        else if (c.is_string() && !c.get<std::string>().empty()) a.clip = c.get<std::string>();
        else r.fail(p + "/clip", "must be a clip's name or its index (a whole number from 0)");
    }
    if (j.contains("speed")) a.speed = r.number(j["speed"], p + "/speed");
    if (j.contains("offset")) a.offset = r.number(j["offset"], p + "/offset");
    if (j.contains("loop")) a.loop = r.flag(j["loop"], p + "/loop");
    return a;
}

SceneObject read_object(const Reader& r, const json& j, const std::string& p, const std::filesystem::path& base) {
    r.fields(j, p,
             {"name", "model", "tree", "scale", "static", "position", "orientation", "velocity", "angular_velocity",
              "path", "animation", "mesh", "mass", "density", "friction", "restitution", "rolling_friction"});
    SceneObject o;
    if (!j.contains("name")) r.fail(p, "object needs a 'name'");
    o.name = r.text(j["name"], p + "/name");
    if (o.name.empty()) r.fail(p + "/name", "must not be empty");
    if (!j.contains("model")) r.fail(p, "object needs a 'model'");
    const std::string model = r.text(j["model"], p + "/model");
    if (model.empty()) r.fail(p + "/model", "must not be empty");
    o.model_path = (base / model).lexically_normal().string();
    if (j.contains("mesh")) {
        const std::string mesh = r.text(j["mesh"], p + "/mesh");
        if (mesh.empty()) r.fail(p + "/mesh", "must not be empty");
        o.mesh_path = (base / mesh).lexically_normal().string();
    }
    if (j.contains("tree")) o.tree = r.text(j["tree"], p + "/tree");
    if (j.contains("scale")) {
        o.scale = r.number(j["scale"], p + "/scale");
        if (!(o.scale > 0)) r.fail(p + "/scale", "must be positive");
    }
    if (j.contains("animation")) {
        o.animated = true;
        o.animation = read_animation(r, j["animation"], p + "/animation");
    }
    if (j.contains("mass") && j.contains("density")) r.fail(p, "an object has a 'mass' or a 'density', not both");
    const double positive = std::numeric_limits<double>::denorm_min(); // the least above 0
    if (j.contains("mass")) o.mass = r.number_in(j["mass"], p + "/mass", positive, 1e30, "positive and at most 1e30");
    if (j.contains("density"))
        o.density = r.number_in(j["density"], p + "/density", positive, 1e30, "positive and at most 1e30");
    read_contact_settings(r, j, p, o.friction, o.restitution, o.rolling_friction);
    const bool is_static = j.contains("static") && r.flag(j["static"], p + "/static");
    const bool moving = j.contains("velocity") || j.contains("angular_velocity");
    if (is_static && (moving || j.contains("path")))
        r.fail(p, "a static object has no velocity, angular_velocity or path");
    if (j.contains("path") && moving) r.fail(p, "an object has velocities or a path, not both");
    if (j.contains("path") && (j.contains("position") || j.contains("orientation")))
        r.fail(p, "an object on a path takes its pose from the keyframes: no 'position' or 'orientation'");
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    if (j.contains("position")) position = r.vec3(j["position"], p + "/position");
    if (j.contains("orientation")) orientation = r.quat(j["orientation"], p + "/orientation");
    if (j.contains("velocity")) o.velocity = r.vec3(j["velocity"], p + "/velocity");
    if (j.contains("angular_velocity")) o.angular_velocity = r.vec3(j["angular_velocity"], p + "/angular_velocity");
    if (j.contains("path")) {
        o.motion = MotionKind::Path;
        o.path = read_path(r, j["path"], p + "/path");
        o.pose = path_pose(o.path, 0);
    } else {
        o.motion = is_static ? MotionKind::Static : MotionKind::Velocity;
        o.pose = Pose::from(position, orientation);
    }
    return o;
}

} // namespace

Scene parse_scene(const std::string& text, const std::string& file, const std::string& base_dir) {
    const Reader r(file);
    const json j = json::parse(text, nullptr, false);
    if (j.is_discarded()) throw Error(ErrorKind::BadInput, file + ": " + detail::json_syntax_problem(text));
    r.fields(j, "", {"spt_scene", "dt", "steps", "gravity", "effects", "response", "dynamics", "level", "objects"});
    Scene s;
    s.file = file;
    if (!j.contains("spt_scene")) r.fail("", "not a scene file: 'spt_scene' is missing");
    if (!j["spt_scene"].is_number_integer() || j["spt_scene"].get<int64_t>() != 1)
        r.fail("/spt_scene", "this build reads scene format 1");
    if (j.contains("dt")) {
        s.dt = r.number(j["dt"], "/dt");
        if (!(s.dt > 0)) r.fail("/dt", "must be positive, not " + j["dt"].dump());
    }
    if (j.contains("steps")) {
        if (!j["steps"].is_number_integer() || j["steps"].get<int64_t>() < 0 || j["steps"].get<int64_t>() > 1000000000)
            r.fail("/steps", "must be a whole number from 0 to 1e9");
        s.steps = int(j["steps"].get<int64_t>());
    }
    if (j.contains("gravity")) s.gravity = r.vec3(j["gravity"], "/gravity");
    if (j.contains("effects")) {
        if (!j["effects"].is_array()) r.fail("/effects", "must be an array of effect names");
        std::vector<std::string> names;
        for (size_t i = 0; i < j["effects"].size(); ++i)
            names.push_back(r.text(j["effects"][i], "/effects/" + std::to_string(i)));
        s.effects = parse_effects(names, file + ": at /effects");
    }
    if (j.contains("response")) {
        r.fields(j["response"], "/response", {"rule", "restitution"});
        const json& resp = j["response"];
        if (resp.contains("rule")) {
            const std::string rule = r.text(resp["rule"], "/response/rule");
            if (rule != "backtrack" && rule != "paper")
                r.fail("/response/rule", "must be 'backtrack' or 'paper', not '" + rule + "'");
            s.response.rule = rule == "paper" ? BacktrackRule::Paper : BacktrackRule::Exact;
        }
        if (resp.contains("restitution"))
            s.response.restitution = r.number_in(resp["restitution"], "/response/restitution", 0, 1, "between 0 and 1");
    }
    if (j.contains("dynamics")) {
        r.fields(j["dynamics"], "/dynamics", {"friction", "restitution", "rolling_friction", "iterations"});
        const json& d = j["dynamics"];
        read_contact_settings(r, d, "/dynamics", s.dynamics.friction, s.dynamics.restitution, s.dynamics.rolling_friction);
        if (d.contains("iterations")) {
            const json& it = d["iterations"];
            if (!it.is_number_integer() || it.get<int64_t>() < 1 || it.get<int64_t>() > 1000)
                r.fail("/dynamics/iterations", "must be a whole number from 1 to 1000");
            s.dynamics.iterations = int(it.get<int64_t>());
        }
    }
    if (j.contains("level")) {
        const std::string level = r.text(j["level"], "/level");
        if (const std::optional<QueryLevel> named = query_level_named(level)) s.level = *named;
        else r.fail("/level", "must be 'bounds', 'spheres' or 'exact', not '" + level + "'");
        if (s.level != QueryLevel::Spheres && s.effects.has(Effect::Dynamics))
            r.fail("/level", "effect 'dynamics' takes its contact manifolds from the sampling spheres: the level must be 'spheres'");
    }
    if (!j.contains("objects")) r.fail("", "a scene needs 'objects'");
    if (!j["objects"].is_array()) r.fail("/objects", "must be an array");
    const std::filesystem::path base(base_dir);
    std::set<std::string> names;
    for (size_t i = 0; i < j["objects"].size(); ++i) {
        const std::string p = "/objects/" + std::to_string(i);
        s.objects.push_back(read_object(r, j["objects"][i], p, base));
        if (!names.insert(s.objects.back().name).second)
            r.fail(p + "/name", "name '" + s.objects.back().name + "' is used by an earlier object");
    }
    return s;
}

Scene load_scene(const std::string& path, const std::atomic<bool>* cancel) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ErrorKind::BadInput, path + ": cannot open the scene file");
    std::stringstream buf;
    buf << in.rdbuf();
    Scene s = parse_scene(buf.str(), path, std::filesystem::path(path).parent_path().string());
    load_models(s, cancel);
    return s;
}

} // namespace spt
