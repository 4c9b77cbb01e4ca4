// Writing and checked reading of authoring recipes: steps, strokes, view matrices, rectangles.
#include "io/recipe_codec.hpp"
#include "io/tree_refs.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {
namespace {

constexpr int kMaxViewPixels = 16384;
constexpr uint32_t kMaxClipName = 4096;
constexpr uint32_t kMaxStrokePoints = 1u << 20; // a lasso or brush path: far more than a hand draws

void put_matrix(Writer& w, const Eigen::Matrix4f& m) {
    for (int k = 0; k < 16; ++k) w.put(m.data()[k]); // column-major, as Eigen and OpenGL keep it
}

Eigen::Matrix4f get_matrix(Reader& r, const char* what) {
    const size_t at = r.offset();
    Eigen::Matrix4f m;
    for (int k = 0; k < 16; ++k) m.data()[k] = r.get<float>(what);
    if (!m.allFinite()) r.fail(at, std::string(what) + " is not finite");
    return m;
}

// A step's pose (version 4): the clip's name, empty for the bind pose, and seconds into it.
void put_pose(Writer& w, const RecipePose& pose) {
    w.put_string(pose.clip);
    w.put(pose.time);
}

RecipePose get_pose(Reader& r) {
    RecipePose pose;
    pose.clip = r.get_string("recipe clip name", kMaxClipName);
    const size_t at = r.offset();
    pose.time = r.get<double>("recipe clip time");
    if (!std::isfinite(pose.time) || pose.time < 0) r.fail(at, "recipe clip time is not a finite time >= 0");
    // One encoding of the bind pose, so a file read and written again keeps its bytes.
    if (pose.clip.empty() && pose.time != 0) r.fail(at, "recipe step at the bind pose (no clip) with a time");
    return pose;
}

// A lasso's vertices or a brush's path (version 5): count, then x, y pairs in window pixels.
void put_points(Writer& w, const std::vector<Eigen::Vector2f>& points) {
    w.put(uint32_t(points.size()));
    for (const Eigen::Vector2f& p : points) w.put(p.x()), w.put(p.y());
}

std::vector<Eigen::Vector2f> get_points(Reader& r, const char* what, uint32_t least) {
    size_t at = r.offset();
    const auto n = r.get<uint32_t>(what);
    if (n < least || n > kMaxStrokePoints)
        r.fail(at, std::string(what) + " has " + std::to_string(n) + " points (" + std::to_string(least) + " to " +
                       std::to_string(kMaxStrokePoints) + ")");
    r.need(uint64_t(n) * 8, std::to_string(n) + " " + what + " points");
    std::vector<Eigen::Vector2f> points(n);
    for (Eigen::Vector2f& p : points) {
        at = r.offset();
        p.x() = r.get<float>(what), p.y() = r.get<float>(what);
        if (!p.allFinite()) r.fail(at, std::string(what) + " point is not finite");
    }
    return points;
}

// What follows a version-5 stroke's fixed fields: its shape, by kind.
void put_shape(Writer& w, const RecipeStroke& s) {
    switch (s.kind) {
    case StrokeKind::Lasso: put_points(w, s.points); break;
    case StrokeKind::Brush:
        w.put(s.radius);
        put_points(w, s.points);
        break;
    case StrokeKind::Linked: w.put(s.pick.x()), w.put(s.pick.y()), w.put(s.pick.z()); break;
    default: break;
    }
}

void get_shape(Reader& r, RecipeStroke& s) {
    switch (s.kind) {
    case StrokeKind::Lasso: s.points = get_points(r, "recipe lasso", 3); break;
    case StrokeKind::Brush: {
        const size_t at = r.offset();
        s.radius = r.get<float>("recipe brush radius");
        if (!std::isfinite(s.radius) || s.radius < 0) r.fail(at, "recipe brush radius is not a finite size >= 0");
        s.points = get_points(r, "recipe brush path", 1);
        break;
    }
    case StrokeKind::Linked: {
        const size_t at = r.offset();
        for (int k = 0; k < 3; ++k) s.pick[k] = r.get<double>("recipe linked pick");
        if (!s.pick.allFinite()) r.fail(at, "recipe linked pick point is not finite");
        break;
    }
    default: break;
    }
}

} // namespace

uint32_t recipe_version(const std::vector<RecipeStep>& recipe) {
    uint32_t version = recipe.empty() ? 0 : 3;
    for (const RecipeStep& step : recipe) {
        if (!step.pose.bind()) version = std::max(version, 4u);
        for (const RecipeStroke& s : step.strokes)
            if (s.kind != StrokeKind::Rect) version = std::max(version, 5u);
    }
    return version;
}

std::string recipe_version_mismatch(uint32_t version) {
    switch (version) {
    case 3: return "a version 3 file without recipe steps (written as version 1 or 2)";
    case 4: return "a version 4 file without a recipe step made at a clip's pose (written as version 3 or older)";
    case 5: return "a version 5 file without a lasso, brush, linked, invert, grow or shrink stroke (written as version 4 or older)";
    default: return "a version " + std::to_string(version) + " file whose recipes need another version";
    }
}

void put_recipe(Writer& w, const std::vector<RecipeStep>& recipe, uint32_t version) {
    w.put(uint32_t(recipe.size()));
    for (const RecipeStep& step : recipe) {
        w.put(step.node);
        w.put(uint32_t(step.strokes.size()));
        for (const RecipeStroke& s : step.strokes) {
            put_matrix(w, s.view.view);
            put_matrix(w, s.view.projection);
            w.put(uint8_t(s.view.perspective));
            w.put(uint8_t(s.visible_only));
            w.put(uint8_t(s.mode));
            w.put(uint8_t(version >= 5 ? uint8_t(s.kind) : 0)); // kind from version 5 on, else 0
            w.put(uint32_t(s.view.width)), w.put(uint32_t(s.view.height));
            w.put(s.rect.x0), w.put(s.rect.y0), w.put(s.rect.x1), w.put(s.rect.y1);
            if (version >= 5) put_shape(w, s);
        }
        if (version >= 4) put_pose(w, step.pose);
    }
}

std::vector<RecipeStep> get_recipe(Reader& r, const SamplingTree& tree, uint32_t version) {
    const auto steps = r.get<uint32_t>("recipe step count");
    // A step takes at least 12 bytes: a bound before any allocation.
    r.need(uint64_t(steps) * 12, std::to_string(steps) + " recipe steps");
    std::vector<RecipeStep> recipe(steps);
    for (RecipeStep& step : recipe) {
        step.node = get_inner_node_id(r, tree, "recipe node", "recipe step for node");
        const auto strokes = r.get<uint32_t>("recipe stroke count");
        r.need(uint64_t(strokes) * kStrokeBytes, std::to_string(strokes) + " recipe strokes");
        step.strokes.resize(strokes);
        for (RecipeStroke& s : step.strokes) {
            s.view.view = get_matrix(r, "recipe view matrix");
            s.view.projection = get_matrix(r, "recipe projection matrix");
            size_t at = r.offset();
            const auto perspective = r.get<uint8_t>("recipe stroke"), visible = r.get<uint8_t>("recipe stroke");
            const auto mode = r.get<uint8_t>("recipe stroke"), kind = r.get<uint8_t>("recipe stroke");
            if (perspective > 1 || visible > 1 || mode > 2 || kind > (version >= 5 ? kLastStrokeKind : 0))
                r.fail(at, "recipe stroke flags " + std::to_string(perspective) + " " + std::to_string(visible) + " " +
                               std::to_string(mode) + " " + std::to_string(kind) + " are not valid");
            s.view.perspective = perspective, s.visible_only = visible, s.mode = SelectionMode(mode);
            s.kind = StrokeKind(kind);
            // Invert, grow and shrink neither combine nor look: one encoding, mode replace and not visible-only.
            if (s.is_operation() && (mode != 0 || visible != 0))
                r.fail(at, "recipe invert, grow or shrink stroke with a mode or visible-only flag");
            at = r.offset();
            const auto width = r.get<uint32_t>("recipe view width"), height = r.get<uint32_t>("recipe view height");
            if (width < 1 || height < 1 || width > kMaxViewPixels || height > kMaxViewPixels)
                r.fail(at, "recipe view size " + std::to_string(width) + "x" + std::to_string(height) +
                               " is out of range (1 to 16384 pixels a side)");
            s.view.width = int(width), s.view.height = int(height);
            at = r.offset();
            s.rect.x0 = r.get<float>("recipe rectangle"), s.rect.y0 = r.get<float>("recipe rectangle");
            s.rect.x1 = r.get<float>("recipe rectangle"), s.rect.y1 = r.get<float>("recipe rectangle");
            if (!std::isfinite(s.rect.x0) || !std::isfinite(s.rect.y0) || !std::isfinite(s.rect.x1) ||
                !std::isfinite(s.rect.y1))
                r.fail(at, "recipe rectangle is not finite");
            if (version >= 5) get_shape(r, s);
        }
        if (version >= 4) step.pose = get_pose(r);
    }
    return recipe;
}

} // namespace spt::detail
