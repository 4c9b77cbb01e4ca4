#pragma once
// Sampling spheres ray-cast on the CPU into one view's pixels, for the base layer of a frame.
// Why not GL: llvmpipe spends about a microsecond of setup, binning and block dispatch on every
// primitive however small, and a view of 50,000 spheres a few pixels across is that many
// primitives; a loop over each sphere's few pixels here costs a small fraction of that.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace spt::render::detail {

/// A sphere as the splat reads it: centre and radius in its item's object frame (model units),
/// colour RGBA8. The layout of the renderer's sphere sets.
struct SplatSphere {
    float center[3];
    float radius;
    uint8_t rgba[4];
};

/// A run of spheres drawn one way: what the GL sphere shader took as uniforms.
struct SplatItem {
    const SplatSphere* spheres = nullptr; ///< `count` spheres
    uint32_t count = 0;
    uint32_t first_index = 0;             ///< index of spheres[0] in its set (ids are index + 1)
    Eigen::Matrix4f model_view = Eigen::Matrix4f::Identity(); ///< object frame to view frame
    bool override_color = false;          ///< `color` replaces each sphere's colour
    Eigen::Vector4f color = Eigen::Vector4f::Ones();
    float fade = 0;                       ///< 0: as coloured; 1: light grey (dimmed)
    bool use_mark = false;                ///< ids are written and marked spheres take `mark_color`
    Eigen::Vector4f mark_color = Eigen::Vector4f::Ones();
    const uint8_t* marks = nullptr;       ///< with use_mark: 3 bytes a sphere of the set, non-zero marked
};

/// The nearest sphere at each pixel of a view, with what the base layer keeps of it.
/// Pixel (x, y) is at index y * width + x, row 0 at the bottom (GL's window order).
class SphereSplat {
public:
    /// Depth of a pixel no sphere covers (window depths are in [0, 1]).
    static constexpr float kEmpty = 2.0f;
    /// Bit of `ids` set when the sphere is drawn marked (its colour is `marked`).
    static constexpr uint32_t kMarkedNow = 0x80000000u;

    /// Starts a view of width x height pixels with projection `projection` (view frame to clip), a
    /// Camera's: no skew or shift; std::invalid_argument for another.
    void begin(int width, int height, const Eigen::Matrix4f& projection, bool ortho);
    /// Queues spheres, drawn after those queued before (a later sphere wins a tie in depth); the
    /// item's arrays must live until run().
    void add(const SplatItem& item);
    /// Ray-casts every queued sphere at each pixel centre it may cover, on up to `threads`
    /// threads (the result does not depend on the number), and empties the queue.
    void run(int threads);

    /// Pixels across, as begun.
    int width() const { return width_; }
    /// Pixels down, as begun.
    int height() const { return height_; }
    /// Window depth of the nearest sphere, or kEmpty.
    const std::vector<float>& depth() const { return depth_; }
    /// RGBA8 (r in the low byte) of the nearest sphere as if it were not marked.
    const std::vector<uint32_t>& plain() const { return plain_; }
    /// RGBA8 of the nearest sphere as if it were marked.
    const std::vector<uint32_t>& marked() const { return marked_; }
    /// Sphere index in its set + 1 for items with marks, else 0; kMarkedNow when drawn marked.
    const std::vector<uint32_t>& ids() const { return ids_; }
    /// Smallest rectangle [x0, x1) x [y0, y1) holding every covered pixel (all 0 if none): its
    /// left column.
    int x0() const { return x0_; }
    /// Its bottom row.
    int y0() const { return y0_; }
    /// One past its right column.
    int x1() const { return x1_; }
    /// One past its top row.
    int y1() const { return y1_; }

private:
    // A queued sphere: view-frame centre and radius, the pixels it may cover, where it came from.
    struct Placed {
        float c[3];
        float r;
        int px0, px1, py0, py1; // inclusive pixel ranges
        uint32_t item, sphere;
    };
    Placed place(uint32_t item, uint32_t sphere) const;
    Placed clip_box(Placed p, float xmin, float xmax, float ymin, float ymax) const;
    void rows(int row0, int row1, int& x0, int& x1, int& y0, int& y1);
    template <bool kOrtho>
    void rows_of(int row0, int row1, int& x0, int& x1, int& y0, int& y1);

    int width_ = 0, height_ = 0;
    bool ortho_ = true;
    Eigen::Matrix4f projection_ = Eigen::Matrix4f::Identity();
    std::vector<float> column_, row_; // the ray under each pixel centre: its x by column, y by row
    std::vector<SplatItem> items_;
    std::vector<Placed> placed_;
    std::vector<float> depth_;
    std::vector<uint32_t> steps_;  // depth_ in the 24-bit depth buffer's steps; UINT32_MAX where empty
    std::vector<uint32_t> winner_; // where steps_ is set: the index in placed_ of the sphere there
    std::vector<uint32_t> plain_, marked_, ids_;
    int x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0;
};

} // namespace spt::render::detail
