// Field-by-field equality of Frame and Camera, for the renderer's frame cache.
#include "frame_equal.hpp"

namespace spt::render::detail {
namespace {

bool eq(const Color& a, const Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }
bool eq(const std::optional<Color>& a, const std::optional<Color>& b) {
    return a.has_value() == b.has_value() && (!a || eq(*a, *b));
}
bool eq(const Sphere& a, const Sphere& b) { return a.center == b.center && a.radius == b.radius; }
bool eq(const Eigen::Affine3f& a, const Eigen::Affine3f& b) { return a.matrix() == b.matrix(); }

bool eq(const MeshItem& a, const MeshItem& b) {
    const MeshStyle &s = a.style, &t = b.style;
    return a.mesh.id == b.mesh.id && eq(a.pose, b.pose) && s.shading == t.shading && eq(s.color, t.color) &&
           s.opacity == t.opacity && s.wireframe == t.wireframe && eq(s.wire_color, t.wire_color) &&
           s.points == t.points && eq(s.point_color, t.point_color) && s.point_size == t.point_size;
}
bool eq(const SphereItem& a, const SphereItem& b) {
    return a.spheres.id == b.spheres.id && eq(a.pose, b.pose) && a.first == b.first && a.count == b.count &&
           eq(a.color, b.color) && a.fade == b.fade && eq(a.marked_color, b.marked_color);
}
bool eq(const WireSphere& a, const WireSphere& b) { return eq(a.sphere, b.sphere) && eq(a.color, b.color); }
bool eq(const SpherePair& a, const SpherePair& b) {
    return eq(a.a, b.a) && eq(a.b, b.b) && a.contact == b.contact && a.normal == b.normal && a.depth == b.depth;
}
bool eq(const ContactMark& a, const ContactMark& b) {
    return a.point == b.point && a.normal == b.normal && eq(a.color, b.color);
}
bool eq(const Trail& a, const Trail& b) { return a.points == b.points && eq(a.color, b.color); }
template <class T> bool eq(const std::vector<T>& a, const std::vector<T>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (!eq(a[i], b[i])) return false;
    return true;
}

bool eq(const CollisionOverlay& a, const CollisionOverlay& b) {
    return eq(a.pairs, b.pairs) && eq(a.color_a, b.color_a) && eq(a.color_b, b.color_b) &&
           eq(a.contact_color, b.contact_color) && eq(a.normal_color, b.normal_color) &&
           a.normal_length == b.normal_length && a.contact_size == b.contact_size && eq(a.marks, b.marks) &&
           eq(a.mark_normal_color, b.mark_normal_color) && a.mark_size == b.mark_size;
}

} // namespace

bool same_frame(const Frame& a, const Frame& b) {
    return eq(a.meshes, b.meshes) && eq(a.spheres, b.spheres) && eq(a.wire_spheres, b.wire_spheres) &&
           eq(a.collision, b.collision) && eq(a.trails, b.trails) && a.grid == b.grid && a.axes == b.axes &&
           eq(a.background, b.background);
}

bool same_camera(const Camera& a, const Camera& b) {
    return a.view == b.view && a.target == b.target && a.radius == b.radius && a.zoom == b.zoom && a.yaw == b.yaw &&
           a.pitch == b.pitch && a.fov_y == b.fov_y;
}

} // namespace spt::render::detail
