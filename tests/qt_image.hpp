#pragma once
// A widget's grabbed framebuffer as a render::Image, for the Qt apps' golden comparisons.
#include "spt/render/image.hpp"
#include <QImage>
#include <cstring>

namespace spt::test {

/// The framebuffer's bytes as drawn: Qt labels a grab premultiplied, and converting it to
/// straight alpha would rescale every see-through pixel, so only the byte order is changed.
inline render::Image to_image(const QImage& grabbed) {
    QImage q = grabbed;
    if (q.format() != QImage::Format_RGBA8888_Premultiplied && q.format() != QImage::Format_RGBA8888)
        q = q.convertToFormat(q.hasAlphaChannel() ? QImage::Format_RGBA8888_Premultiplied : QImage::Format_RGBA8888);
    render::Image out;
    out.width = q.width();
    out.height = q.height();
    out.rgba.resize(size_t(out.width) * size_t(out.height) * 4);
    for (int y = 0; y < q.height(); ++y) std::memcpy(out.pixel(0, y), q.constScanLine(y), size_t(out.width) * 4);
    return out;
}

} // namespace spt::test
