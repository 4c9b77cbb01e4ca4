// The closed list of effects (names, dependencies) and keyframed paths.
#include "spt/error.hpp"
#include "spt/scene.hpp"
#include <algorithm>
#include <sstream>

namespace spt {
namespace {

constexpr const char* kNames[kEffectCount] = {"motion",   "gravity", "contacts", "depth", "pairs",
                                              "response", "ccd",     "exact",    "deform", "dynamics"};

// What each effect needs: an effect never switches another on silently.
std::vector<Effect> needs(Effect e) {
    switch (e) {
    case Effect::Gravity: return {Effect::Motion};
    case Effect::Depth: return {Effect::Contacts};
    case Effect::Pairs: return {Effect::Contacts};
    case Effect::Response: return {Effect::Depth};
    case Effect::Ccd: return {Effect::Contacts, Effect::Motion};
    case Effect::Exact: return {Effect::Contacts};
    case Effect::Dynamics: return {Effect::Contacts, Effect::Motion};
    default: return {};
    }
}

// Effects that cannot run with `e`, and why (said after naming both).
std::vector<std::pair<Effect, const char*>> excludes(Effect e) {
    if (e != Effect::Dynamics) return {};
    return {{Effect::Response, "both move colliding objects: the paper's rule moves them back, the solver pushes them apart"},
            {Effect::Ccd, "the solver finds contacts ahead of the motion itself (speculative contacts within the step's travel)"},
            {Effect::Exact, "the solver's contact manifolds come from the sampling spheres"}};
}

std::string known_list() {
    std::string s;
    for (int i = 0; i < kEffectCount; ++i) s += (i ? ", " : "") + std::string(kNames[i]);
    return s;
}

} // namespace

const char* effect_name(Effect e) { return kNames[int(e)]; }

std::string EffectSet::names() const {
    std::string s;
    for (int i = 0; i < kEffectCount; ++i)
        if (has(Effect(i))) s += (s.empty() ? "" : ",") + std::string(kNames[i]);
    return s;
}

EffectSet parse_effects(const std::vector<std::string>& names, const std::string& where) {
    EffectSet set;
    const std::string prefix = where.empty() ? "" : where + ": ";
    for (const std::string& n : names) {
        const auto* it = std::find(std::begin(kNames), std::end(kNames), n);
        if (it == std::end(kNames))
            throw Error(ErrorKind::BadInput,
                        prefix + "unknown effect '" + n + "' (the effects are: " + known_list() + ")");
        set.add(Effect(it - std::begin(kNames)));
    }
    for (int i = 0; i < kEffectCount; ++i) {
        if (!set.has(Effect(i))) continue;
        for (Effect need : needs(Effect(i)))
            if (!set.has(need))
                throw Error(ErrorKind::BadInput, prefix + "effect '" + kNames[i] + "' needs effect '" +
                                                     effect_name(need) + "', which is not listed");
        for (const auto& [other, why] : excludes(Effect(i)))
            if (set.has(other))
                throw Error(ErrorKind::BadInput, prefix + "effects '" + effect_name(other) + "' and '" + kNames[i] +
                                                     "' cannot run together: " + why);
    }
    return set;
}

EffectSet parse_effect_list(const std::string& comma_separated, const std::string& where) {
    std::vector<std::string> names;
    std::stringstream in(comma_separated);
    std::string item;
    while (std::getline(in, item, ','))
        if (!item.empty()) names.push_back(item);
    return parse_effects(names, where);
}

Pose path_pose(const std::vector<Keyframe>& path, double t) {
    if (path.empty()) return {};
    if (t <= path.front().t) return Pose::from(path.front().position, path.front().orientation);
    if (t >= path.back().t) return Pose::from(path.back().position, path.back().orientation);
    const auto next = std::upper_bound(path.begin(), path.end(), t, [](double v, const Keyframe& k) { return v < k.t; });
    const Keyframe& k1 = *next;
    const Keyframe& k0 = *(next - 1);
    const double u = (t - k0.t) / (k1.t - k0.t);
    return interpolate(Pose::from(k0.position, k0.orientation), Pose::from(k1.position, k1.orientation), u);
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> path_velocity(const std::vector<Keyframe>& path, double t) {
    const std::pair<Eigen::Vector3d, Eigen::Vector3d> still{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    if (path.size() < 2 || t < path.front().t || t >= path.back().t) return still;
    const auto next = std::upper_bound(path.begin(), path.end(), t, [](double v, const Keyframe& k) { return v < k.t; });
    const Keyframe &k1 = *next, &k0 = *(next - 1);
    const double span = k1.t - k0.t;
    // Slerp turns at a constant rate about a fixed world axis: that of q1 q0^-1, the shorter way.
    Eigen::Quaterniond turn = unit_quaternion(k1.orientation) * unit_quaternion(k0.orientation).conjugate();
    if (turn.w() < 0) turn.coeffs() = -turn.coeffs();
    const Eigen::AngleAxisd aa(turn);
    return {(k1.position - k0.position) / span, aa.axis() * (aa.angle() / span)};
}

} // namespace spt
