// A software depth buffer of a mesh in one view, for visible-only selection.
#include "spt/selection.hpp"
#include "selection/window_point.hpp"
#include "base/parallel.hpp"
#include <algorithm>
#include <cmath>

namespace spt {

namespace {

// Draws the pixels [px0, px1] x [py0, py1] (inclusive, already inside the map) of the depth map.
DepthMap draw_depth(const TriangleMesh& mesh, const ViewProjection& view, int px0, int py0, int px1, int py1) {
    DepthMap map;
    map.width = std::max(view.width, 1);
    map.height = std::max(view.height, 1);
    map.depth.assign(size_t(map.width) * size_t(map.height), INFINITY);
    if (px0 > px1 || py0 > py1) return map;
    const int threads = detail::machine_threads();
    constexpr size_t kChunk = size_t(1) << 16; // vertices or triangles a thread takes at a time
    std::vector<Eigen::Vector3f> win(mesh.positions.size());
    // Which side of the drawn pixels each vertex lies beyond (bits: left, right, below, above),
    // a quarter pixel clear of the pixel centres' box test below: a triangle with all three
    // corners beyond one side holds no centre it draws, and is skipped with three byte reads.
    std::vector<uint8_t> beyond(mesh.positions.size());
    const float left = float(px0) + 0.25f, right = float(px1) + 0.75f;
    const float below = float(py0) + 0.25f, above = float(py1) + 0.75f;
    const detail::WindowMap window(view);
    detail::parallel_for((win.size() + kChunk - 1) / kChunk, threads, [&](size_t c, int) {
        for (size_t i = c * kChunk, e = std::min(win.size(), i + kChunk); i < e; ++i) {
            const Eigen::Vector3f w = window(mesh.positions[i]);
            win[i] = w;
            beyond[i] = uint8_t(int(w.x() < left) | int(w.x() > right) << 1 | int(w.y() < below) << 2 |
                                int(w.y() > above) << 3);
        }
    });
    // Screen-space interpolation: eye depth is affine in x, y for an orthographic view;
    // for a perspective one its reciprocal is.
    auto value = [&](float z) { return view.perspective ? 1.0f / z : z; };
    auto depth = [&](float v) { return view.perspective ? 1.0f / v : v; };
    // The triangles in consecutive parts, each part's nearest depths over the drawn pixels kept
    // apart and merged in part order: a tie keeps the first depth drawn (+0 before -0), as one
    // pass over the triangles in order does, whatever the thread count.
    const int span_x = px1 - px0 + 1, span_y = py1 - py0 + 1;
    const size_t nt = mesh.triangles.size(), parts = std::min<size_t>(4 * size_t(threads), nt / kChunk + 1);
    std::vector<std::vector<float>> nearest(parts);
    auto draw = [&](const Triangle& t, std::vector<float>& out) {
        if (beyond[t[0]] & beyond[t[1]] & beyond[t[2]]) return;
        const Eigen::Vector3f &a = win[t[0]], &b = win[t[1]], &c = win[t[2]];
        if (view.perspective && (a.z() <= 0 || b.z() <= 0 || c.z() <= 0)) return;
        const float area = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
        if (area == 0 || !std::isfinite(area)) return;
        // The pixels whose centres (x + 0.5, y + 0.5) lie in the triangle's box, widened by a
        // pixel's hundredth for the rounding of the weights below: a triangle smaller than a
        // pixel (a million-vertex mesh in a small view) mostly holds no centre and costs no test.
        const float slack = 0.01f;
        const int x0 = std::max(px0, int(std::ceil(std::min({a.x(), b.x(), c.x()}) - 0.5f - slack)));
        const int x1 = std::min(px1, int(std::floor(std::max({a.x(), b.x(), c.x()}) - 0.5f + slack)));
        const int y0 = std::max(py0, int(std::ceil(std::min({a.y(), b.y(), c.y()}) - 0.5f - slack)));
        const int y1 = std::min(py1, int(std::floor(std::max({a.y(), b.y(), c.y()}) - 0.5f + slack)));
        if (x0 > x1 || y0 > y1) return;
        if (out.empty()) out.assign(size_t(span_x) * size_t(span_y), INFINITY);
        const float va = value(a.z()), vb = value(b.z()), vc = value(c.z());
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const float px = float(x) + 0.5f, py = float(y) + 0.5f;
                // Barycentric weights; either winding is drawn (no culling: back faces hide too).
                const float wa = ((b.x() - px) * (c.y() - py) - (c.x() - px) * (b.y() - py)) / area;
                const float wb = ((c.x() - px) * (a.y() - py) - (a.x() - px) * (c.y() - py)) / area;
                const float wc = 1.0f - wa - wb;
                if (wa < 0 || wb < 0 || wc < 0) continue;
                const float d = depth(wa * va + wb * vb + wc * vc);
                float& slot = out[size_t(y - py0) * size_t(span_x) + size_t(x - px0)];
                slot = std::min(slot, d);
            }
    };
    detail::parallel_for(parts, threads, [&](size_t p, int) {
        for (size_t i = nt * p / parts, e = nt * (p + 1) / parts; i < e; ++i) draw(mesh.triangles[i], nearest[p]);
    });
    for (const std::vector<float>& part : nearest) {
        if (part.empty()) continue;
        for (int y = 0; y < span_y; ++y) {
            float* row = map.depth.data() + size_t(py0 + y) * size_t(map.width) + size_t(px0);
            const float* from = part.data() + size_t(y) * size_t(span_x);
            for (int x = 0; x < span_x; ++x) row[x] = std::min(row[x], from[x]);
        }
    }
    return map;
}

} // namespace

DepthMap render_depth(const TriangleMesh& mesh, const ViewProjection& view) {
    return draw_depth(mesh, view, 0, 0, std::max(view.width, 1) - 1, std::max(view.height, 1) - 1);
}

DepthMap render_depth(const TriangleMesh& mesh, const ViewProjection& view, const PixelRect& window) {
    const int w = std::max(view.width, 1), h = std::max(view.height, 1);
    // The pixels a sample inside the window reads: its own and its neighbours (visible_samples_in_rect).
    const auto lo = [](float a, float b) { return std::floor(std::min(a, b)) - 1.0f; };
    const auto hi = [](float a, float b) { return std::floor(std::max(a, b)) + 1.0f; };
    const float fx0 = lo(window.x0, window.x1), fx1 = hi(window.x0, window.x1);
    const float fy0 = lo(window.y0, window.y1), fy1 = hi(window.y0, window.y1);
    if (!(fx0 <= fx1 && fy0 <= fy1)) return draw_depth(mesh, view, 0, 0, -1, -1); // NaN corners: nothing inside
    const int x0 = int(std::clamp(fx0, 0.0f, float(w))), x1 = int(std::clamp(fx1, -1.0f, float(w - 1)));
    const int y0 = int(std::clamp(fy0, 0.0f, float(h))), y1 = int(std::clamp(fy1, -1.0f, float(h - 1)));
    return draw_depth(mesh, view, x0, y0, x1, y1);
}

} // namespace spt
