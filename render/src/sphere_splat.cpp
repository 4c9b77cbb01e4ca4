// Sampling spheres ray-cast on the CPU: the sums of the GL impostor shader they replace, per pixel.
#include "sphere_splat.hpp"
#include "spt/task_system.hpp"
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spt::render::detail {
namespace {

// Steps of the layers' 24-bit depth buffer.
constexpr float kDepthSteps = 16777215.0f;

inline uint32_t to_rgba8(float r, float g, float b, float a) {
    const auto u8 = [](float v) { return uint32_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
    return u8(r) | u8(g) << 8 | u8(b) << 16 | u8(a) << 24;
}

float smoothstep(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// A sphere's two colours before lighting, as the GL shader made them per vertex.
struct Colours {
    float plain[4], marked[4];
    uint32_t id;
};

Colours colours_of(const SplatItem& it, uint32_t sphere) {
    static constexpr float kGrey[3] = {0.84f, 0.85f, 0.87f};
    const SplatSphere& s = it.spheres[sphere];
    Colours c;
    for (int k = 0; k < 4; ++k) c.plain[k] = it.override_color ? it.color[k] : float(s.rgba[k]) / 255.0f;
    for (int k = 0; k < 3; ++k) c.plain[k] = c.plain[k] * (1 - it.fade) + kGrey[k] * it.fade;
    const uint32_t index = it.first_index + sphere;
    for (int k = 0; k < 4; ++k) c.marked[k] = it.use_mark ? it.mark_color[k] : c.plain[k];
    if (it.use_mark)
        for (int k = 0; k < 3; ++k) c.marked[k] = c.marked[k] * (1 - it.fade) + kGrey[k] * it.fade;
    const bool marked_now = it.use_mark && it.marks && it.marks[3 * size_t(index)] != 0;
    c.id = (it.use_mark ? index + 1 : 0) | (marked_now ? SphereSplat::kMarkedNow : 0);
    return c;
}

} // namespace

void SphereSplat::begin(int width, int height, const Eigen::Matrix4f& projection, bool ortho) {
    // The renderer's cameras project without skew or shift (camera.cpp); the rays below rely on it.
    const Eigen::Matrix4f& P = projection;
    if (P(0, 1) != 0 || P(1, 0) != 0 || P(3, 0) != 0 || P(3, 1) != 0 || P(2, 0) != 0 || P(2, 1) != 0 ||
        (ortho ? P(3, 2) != 0 || P(0, 2) != 0 || P(1, 2) != 0 : P(0, 3) != 0 || P(1, 3) != 0))
        throw std::invalid_argument("SphereSplat: the projection is not a camera's");
    width_ = std::max(0, width), height_ = std::max(0, height);
    ortho_ = ortho;
    projection_ = projection;
    items_.clear();
    placed_.clear();
    const size_t pixels = size_t(width_) * size_t(height_);
    depth_.assign(pixels, kEmpty);
    steps_.assign(pixels, UINT32_MAX);
    plain_.resize(pixels), marked_.resize(pixels), ids_.resize(pixels), winner_.resize(pixels);
    x0_ = y0_ = x1_ = y1_ = 0;
    // Under each pixel centre: orthographic, the view-frame x and y of its ray; perspective, the
    // x and y of its direction where z = -1.
    column_.resize(size_t(width_));
    row_.resize(size_t(height_));
    for (int x = 0; x < width_; ++x) {
        const double ndc = 2.0 * (x + 0.5) / width_ - 1.0;
        column_[size_t(x)] = float(ortho ? (ndc - P(0, 3)) / P(0, 0) : (ndc + P(0, 2)) / P(0, 0));
    }
    for (int y = 0; y < height_; ++y) {
        const double ndc = 2.0 * (y + 0.5) / height_ - 1.0;
        row_[size_t(y)] = float(ortho ? (ndc - P(1, 3)) / P(1, 1) : (ndc + P(1, 2)) / P(1, 1));
    }
}

void SphereSplat::add(const SplatItem& item) {
    if (item.count == 0 || !item.spheres || width_ == 0 || height_ == 0) return;
    items_.push_back(item);
}

// Where sphere `sphere` of item `item` may cover pixels; px0 > px1 if nowhere.
SphereSplat::Placed SphereSplat::place(uint32_t item, uint32_t sphere) const {
    Placed p{{0, 0, 0}, 0, 1, 0, 1, 0, item, sphere};
    const SplatItem& it = items_[item];
    const SplatSphere& s = it.spheres[sphere];
    const Eigen::Vector3f c = (it.model_view * Eigen::Vector4f(s.center[0], s.center[1], s.center[2], 1)).head<3>();
    const float r = s.radius;
    if (!(r > 0) || !c.allFinite() || !std::isfinite(r)) return p;
    p.c[0] = c.x(), p.c[1] = c.y(), p.c[2] = c.z(), p.r = r;
    if (ortho_) {
        // The circle of radius r about the centre, in pixels: the columns' and rows' spacing is even.
        const float x = (projection_(0, 0) * c.x() + projection_(0, 3) + 1) * 0.5f * float(width_);
        const float y = (projection_(1, 1) * c.y() + projection_(1, 3) + 1) * 0.5f * float(height_);
        const float rx = 1.01f * r * std::abs(projection_(0, 0)) * 0.5f * float(width_);
        const float ry = 1.01f * r * std::abs(projection_(1, 1)) * 0.5f * float(height_);
        return clip_box(p, x - rx, x + rx, y - ry, y + ry);
    }
    // Perspective, the outline is the circle where the eye's tangent cone crosses the plane through
    // the centre: a square around it, a little wider, projects over every pixel the sphere covers.
    const float d = c.norm();
    if (d <= r * 1.001f) return p; // the eye inside the sphere: the GL shader drew nothing
    // Wholly nearer than the near plane or beyond the far one: every hit is outside the depth
    // range. Skipped here, so that spheres behind the eye never cost a whole view below.
    const float near = projection_(2, 3) / (projection_(2, 2) - 1), far = projection_(2, 3) / (projection_(2, 2) + 1);
    if (c.z() - r > -near || c.z() + r < -far) return p;
    const Eigen::Vector3f w = c / d;
    const Eigen::Vector3f helper = std::abs(w.y()) < 0.99f ? Eigen::Vector3f::UnitY() : Eigen::Vector3f::UnitX();
    const Eigen::Vector3f u = helper.cross(w).normalized(), v = w.cross(u);
    const float half = 1.01f * r * d / std::sqrt(d * d - r * r);
    float xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int k = 0; k < 4; ++k) {
        const Eigen::Vector3f q = c + ((k & 1) ? half : -half) * u + ((k & 2) ? half : -half) * v;
        const Eigen::Vector4f clip = projection_ * Eigen::Vector4f(q.x(), q.y(), q.z(), 1);
        if (!(clip.w() > 0)) // the square crosses the eye's plane: every pixel is tried
            return clip_box(p, -INFINITY, INFINITY, -INFINITY, INFINITY);
        const float x = (clip.x() / clip.w() * 0.5f + 0.5f) * float(width_);
        const float y = (clip.y() / clip.w() * 0.5f + 0.5f) * float(height_);
        xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
    }
    return clip_box(p, xmin, xmax, ymin, ymax);
}

// p with the pixels whose centres lie in [xmin, xmax] x [ymin, ymax] (window coordinates).
SphereSplat::Placed SphereSplat::clip_box(Placed p, float xmin, float xmax, float ymin, float ymax) const {
    const auto first = [](float lo, int n) { return lo > 0 ? int(std::min(std::ceil(lo - 0.5f), float(n))) : 0; };
    const auto last = [](float hi, int n) { return hi < float(n) ? int(std::max(std::floor(hi - 0.5f), -1.0f)) : n - 1; };
    p.px0 = first(xmin, width_), p.px1 = last(xmax, width_);
    p.py0 = first(ymin, height_), p.py1 = last(ymax, height_);
    return p;
}

namespace {

// Where the ray under a pixel first meets a sphere: the hit and the ray's direction in the view
// frame, and the hit's window depth.
struct Hit {
    float x, y, z, dx, dy, dz, depth;
};

// The sums of the GL impostor shader for the ray under the pixel whose ray has x `rx` and y
// `ry` (SphereSplat::begin); false if it misses. The same inputs give the same bits, so both
// passes of SphereSplat::rows find the same hit.
template <bool kOrtho>
inline bool ray_hit(float cx, float cy, float cz, float rr, float rx, float ry, const Eigen::Matrix4f& P, Hit& h) {
    if (kOrtho) {
        const float disc = (rr - (ry - cy) * (ry - cy)) - (rx - cx) * (rx - cx);
        if (!(disc >= 0)) return false;
        h = {rx, ry, cz + std::sqrt(disc), 0, 0, -1, 0};
        h.depth = 0.5f * (P(2, 2) * h.z + P(2, 3)) + 0.5f; // w = 1
    } else {
        const float inv = 1.0f / std::sqrt(rx * rx + ry * ry + 1.0f);
        const float dx = rx * inv, dy = ry * inv, dz = -inv;
        // r^2 less the squared distance of the centre from the ray, taken from the perpendicular
        // itself: b^2 - |c|^2 + r^2 would cancel away most digits of a small sphere far from the eye.
        const float b = -(dx * cx + dy * cy + dz * cz);
        const float qx = cx + b * dx, qy = cy + b * dy, qz = cz + b * dz;
        const float disc = rr - (qx * qx + qy * qy + qz * qz);
        if (!(disc >= 0)) return false;
        const float t = -b - std::sqrt(disc);
        h = {t * dx, t * dy, t * dz, dx, dy, dz, 0};
        h.depth = 0.5f * ((P(2, 2) * h.z + P(2, 3)) / (P(3, 2) * h.z + P(3, 3))) + 0.5f;
    }
    return h.depth >= 0 && h.depth <= 1;
}

} // namespace

// The queued spheres over rows [row0, row1); (x0, x1, y0, y1) grows to the pixels covered.
void SphereSplat::rows(int row0, int row1, int& x0, int& x1, int& y0, int& y1) {
    if (ortho_)
        rows_of<true>(row0, row1, x0, x1, y0, y1);
    else
        rows_of<false>(row0, row1, x0, x1, y0, y1);
}

// Two passes: the nearest sphere at each pixel, then the colours of that one only (the spheres of
// a surface overlap many times over, and most of their hits are hidden).
template <bool kOrtho>
void SphereSplat::rows_of(int row0, int row1, int& x0, int& x1, int& y0, int& y1) {
    const Eigen::Matrix4f& P = projection_;
    // Orthographic columns are evenly spaced: a row's hits lie in a span found from the circle.
    const float x_step = width_ > 1 ? column_[1] - column_[0] : 1.0f;
    const float* column = column_.data();
    uint32_t* steps = steps_.data();
    uint32_t* winner = winner_.data();
    for (uint32_t k = 0; k < placed_.size(); ++k) {
        const Placed& s = placed_[k];
        const int ya = std::max(s.py0, row0), yb = std::min(s.py1, row1 - 1);
        if (ya > yb || s.px0 > s.px1) continue;
        const float cx = s.c[0], cy = s.c[1], cz = s.c[2], rr = s.r * s.r;
        for (int y = ya; y <= yb; ++y) {
            const float ry = row_[size_t(y)];
            int xa = s.px0, xb = s.px1;
            if (kOrtho) {
                const float rem = rr - (ry - cy) * (ry - cy);
                if (!(rem >= 0)) continue;
                const float reach = std::sqrt(rem) / std::abs(x_step);
                const float mid = (cx - column[0]) / x_step;
                // Widened by a thousandth of a pixel for the rounding of the columns' x.
                xa = std::max(xa, int(std::ceil(mid - reach - 1e-3f))), xb = std::min(xb, int(std::floor(mid + reach + 1e-3f)));
            }
            const size_t row = size_t(y) * size_t(width_);
            for (int x = xa; x <= xb; ++x) {
                Hit h;
                if (!ray_hit<kOrtho>(cx, cy, cz, rr, column[x], ry, P, h)) continue;
                // Compared in the 24-bit depth buffer's steps, so that two spheres crossing are
                // told apart as GL told them apart (a tie goes to the later sphere).
                const uint32_t step = uint32_t(h.depth * kDepthSteps + 0.5f);
                const size_t i = row + size_t(x);
                if (step > steps[i]) continue;
                steps[i] = step;
                winner[i] = k;
            }
        }
    }
    for (int y = row0; y < row1; ++y) {
        const size_t row = size_t(y) * size_t(width_);
        for (int x = 0; x < width_; ++x) {
            const size_t i = row + size_t(x);
            if (steps[i] == UINT32_MAX) continue;
            const Placed& s = placed_[winner[i]];
            Hit h{};
            ray_hit<kOrtho>(s.c[0], s.c[1], s.c[2], s.r * s.r, column[x], row_[size_t(y)], P, h);
            const float inv_r = 1.0f / s.r;
            const float nx = (h.x - s.c[0]) * inv_r, ny = (h.y - s.c[1]) * inv_r, nz = (h.z - s.c[2]) * inv_r;
            // shade() of the GL shaders (a headlight up and to the left, two-sided) and the darker rim.
            const float light = 0.30f + 0.58f * std::abs(nx * -0.3333f + ny * 0.6667f + nz * 0.6667f) + 0.12f * std::abs(nz);
            const float facing = std::clamp(-(nx * h.dx + ny * h.dy + nz * h.dz), 0.0f, 1.0f);
            const float k = light * (0.55f + 0.45f * smoothstep(0.0f, 0.45f, facing));
            const Colours col = colours_of(items_[s.item], s.sphere);
            depth_[i] = float(steps[i]) / kDepthSteps;
            plain_[i] = to_rgba8(col.plain[0] * k, col.plain[1] * k, col.plain[2] * k, col.plain[3]);
            marked_[i] = to_rgba8(col.marked[0] * k, col.marked[1] * k, col.marked[2] * k, col.marked[3]);
            ids_[i] = col.id;
            x0 = std::min(x0, x), x1 = std::max(x1, x + 1), y0 = std::min(y0, y), y1 = std::max(y1, y + 1);
        }
    }
}

void SphereSplat::run(int threads) {
    size_t total = 0;
    for (const SplatItem& it : items_) total += it.count;
    placed_.resize(total);
    const int parts = total < 4096 ? 1 : std::max(1, threads);
    const auto place_part = [&](int k) {
        size_t i = 0;
        const size_t begin = total * size_t(k) / size_t(parts), end = total * size_t(k + 1) / size_t(parts);
        for (uint32_t item = 0; item < items_.size(); ++item) {
            const size_t n = items_[item].count;
            for (size_t j = std::max(begin, i); j < std::min(end, i + n); ++j) placed_[j] = place(item, uint32_t(j - i));
            i += n;
        }
    };
    spt::run_parallel(parts, [&](int k) { place_part(k); });
    // Bands of rows, each drawn by one thread in queue order: every pixel sees the spheres in
    // the same order whatever the number of bands.
    const int bands = placed_.size() < 2048 ? 1 : std::clamp(threads, 1, std::max(1, height_ / 16));
    struct Box {
        int x0, x1, y0, y1;
    };
    std::vector<Box> boxes(size_t(bands), Box{width_, 0, height_, 0});
    const auto band = [&](int k) {
        Box& b = boxes[size_t(k)];
        rows(int(int64_t(height_) * k / bands), int(int64_t(height_) * (k + 1) / bands), b.x0, b.x1, b.y0, b.y1);
    };
    spt::run_parallel(bands, [&](int k) { band(k); });
    x0_ = width_, x1_ = 0, y0_ = height_, y1_ = 0;
    for (const Box& b : boxes)
        x0_ = std::min(x0_, b.x0), x1_ = std::max(x1_, b.x1), y0_ = std::min(y0_, b.y0), y1_ = std::max(y1_, b.y1);
    if (x0_ >= x1_ || y0_ >= y1_) x0_ = y0_ = x1_ = y1_ = 0;
    items_.clear();
    placed_.clear();
}

} // namespace spt::render::detail
