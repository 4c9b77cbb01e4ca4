#pragma once
// A view's map from object frame to window pixels, composed once per selection in double:
// one product a point instead of two float matrix products, and no float rounding of
// coordinates far from the origin before the view's translation takes them back.
#include "spt/split_recipe.hpp"
#include <Eigen/Core>
#include <algorithm>

namespace spt::detail {

class WindowMap {
public:
    explicit WindowMap(const ViewProjection& view) : perspective_(view.perspective) {
        const Eigen::Matrix4d v = view.view.cast<double>();
        const Eigen::Matrix4d clip = view.projection.cast<double>() * v;
        const double hw = 0.5 * double(std::max(view.width, 1)), hh = 0.5 * double(std::max(view.height, 1));
        // Window x = (clip.x / w + 1) * width / 2 = (clip.x + w) * (width / 2) / w, with w = 1
        // for an orthographic view whatever the matrix's last row says.
        const Eigen::RowVector4d w = perspective_ ? Eigen::RowVector4d(clip.row(3)) : Eigen::RowVector4d(0, 0, 0, 1);
        const Eigen::RowVector4d rows[4] = {hw * (clip.row(0) + w), hh * (clip.row(1) + w), -v.row(2), w};
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) m_[r][c] = rows[r][c];
    }

    bool perspective() const { return perspective_; }

    /// Window x, y (pixels) and eye depth (model units in front of the eye) of object-frame p.
    Eigen::Vector3f operator()(const Eigen::Vector3d& p) const {
        return perspective_ ? map<true>(p.x(), p.y(), p.z()) : map<false>(p.x(), p.y(), p.z());
    }

    /// As operator(), with the view's kind fixed for a loop.
    template <bool Perspective> Eigen::Vector3f map(double x, double y, double z) const {
        const double wx = m_[0][0] * x + m_[0][1] * y + m_[0][2] * z + m_[0][3];
        const double wy = m_[1][0] * x + m_[1][1] * y + m_[1][2] * z + m_[1][3];
        const double ez = m_[2][0] * x + m_[2][1] * y + m_[2][2] * z + m_[2][3];
        if constexpr (!Perspective) return {float(wx), float(wy), float(ez)};
        const double w = m_[3][0] * x + m_[3][1] * y + m_[3][2] * z + m_[3][3];
        return {float(wx / w), float(wy / w), float(ez)};
    }

private:
    bool perspective_;
    double m_[4][4]; // rows: window x, window y, eye depth, w
};

} // namespace spt::detail
