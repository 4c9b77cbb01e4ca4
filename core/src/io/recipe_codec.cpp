// Writing and checked reading of authoring recipes: steps, strokes, view matrices, rectangles.
#include "io/recipe_codec.hpp"
#include <cmath>

namespace spt::detail {
namespace {

constexpr int kMaxViewPixels = 16384;
constexpr uint32_t kMaxClipName = 4096;

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

} // namespace

bool has_poses(const std::vector<RecipeStep>& recipe) {
    for (const RecipeStep& step : recipe)
        if (!step.pose.bind()) return true;
    return false;
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
            w.put(uint8_t(0));
            w.put(uint32_t(s.view.width)), w.put(uint32_t(s.view.height));
            w.put(s.rect.x0), w.put(s.rect.y0), w.put(s.rect.x1), w.put(s.rect.y1);
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
        size_t at = r.offset();
        step.node = r.get<uint64_t>("recipe node");
        const TreeNode* n = tree.find(step.node);
        if (!n || n->active)
            r.fail(at, "recipe step for node " + std::to_string(step.node) + ": tree '" + tree.name() +
                           "' has no split node with that id");
        const auto strokes = r.get<uint32_t>("recipe stroke count");
        r.need(uint64_t(strokes) * kStrokeBytes, std::to_string(strokes) + " recipe strokes");
        step.strokes.resize(strokes);
        for (RecipeStroke& s : step.strokes) {
            s.view.view = get_matrix(r, "recipe view matrix");
            s.view.projection = get_matrix(r, "recipe projection matrix");
            at = r.offset();
            const auto perspective = r.get<uint8_t>("recipe stroke"), visible = r.get<uint8_t>("recipe stroke");
            const auto mode = r.get<uint8_t>("recipe stroke"), pad = r.get<uint8_t>("recipe stroke");
            if (perspective > 1 || visible > 1 || mode > 2 || pad != 0)
                r.fail(at, "recipe stroke flags " + std::to_string(perspective) + " " + std::to_string(visible) + " " +
                               std::to_string(mode) + " " + std::to_string(pad) + " are not valid");
            s.view.perspective = perspective, s.visible_only = visible, s.mode = SelectionMode(mode);
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
        }
        if (version >= 4) step.pose = get_pose(r);
    }
    return recipe;
}

} // namespace spt::detail
