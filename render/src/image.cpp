// RGBA8 images: deterministic PNG encoding, PNG decoding and files, pixel-by-pixel comparison.
#include "spt/render/image.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <png.h>
#include <sstream>
#include <unistd.h>

namespace spt::render {
namespace {

// libpng reports errors through longjmp by default; turn them into exceptions
// carried out of the C callbacks by a stored message instead.
struct PngError {
    std::string message;
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp msg) {
    auto* err = static_cast<PngError*>(png_get_error_ptr(png));
    if (err) err->message = msg ? msg : "unknown libpng error";
    png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

struct ReadCursor {
    const std::vector<uint8_t>* bytes;
    size_t offset = 0;
};

void read_bytes(png_structp png, png_bytep out, png_size_t n) {
    auto* c = static_cast<ReadCursor*>(png_get_io_ptr(png));
    if (c->offset + n > c->bytes->size()) png_error(png, "file ends early");
    std::memcpy(out, c->bytes->data() + c->offset, n);
    c->offset += n;
}

void write_bytes(png_structp png, png_bytep data, png_size_t n) {
    auto* out = static_cast<std::vector<uint8_t>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + n);
}

void flush_bytes(png_structp) {}

} // namespace

Image Image::filled(int width, int height, uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
    Image im;
    im.width = width, im.height = height;
    im.rgba.resize(size_t(width) * size_t(height) * 4);
    for (size_t i = 0; i < im.rgba.size(); i += 4) im.rgba[i] = r, im.rgba[i + 1] = g, im.rgba[i + 2] = b, im.rgba[i + 3] = a;
    return im;
}

std::vector<uint8_t> encode_png(const Image& image) {
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != size_t(image.width) * size_t(image.height) * 4)
        throw std::invalid_argument("encode_png: image size does not match its pixel data");
    bool opaque = true;
    for (size_t i = 3; i < image.rgba.size() && opaque; i += 4) opaque = image.rgba[i] == 255;
    const int channels = opaque ? 3 : 4;
    std::vector<uint8_t> rows(size_t(image.width) * size_t(image.height) * size_t(channels));
    for (size_t p = 0, n = size_t(image.width) * size_t(image.height); p < n; ++p)
        std::memcpy(&rows[p * size_t(channels)], &image.rgba[p * 4], size_t(channels));

    std::vector<uint8_t> out;
    PngError err;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &err, on_png_error, on_png_warning);
    if (!png) throw std::bad_alloc();
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw std::runtime_error("encode_png: " + err.message);
    }
    png_set_write_fn(png, &out, write_bytes, flush_bytes);
    // Fixed settings: the same pixels give the same bytes on every run.
    // Measured on renders: no row filter and zlib level 3 is both the fastest and the
    // smallest choice (flat backgrounds compress well without filtering).
    png_set_compression_level(png, 3);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8,
                 opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y)
        png_write_row(png, &rows[size_t(y) * size_t(image.width) * size_t(channels)]);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return out;
}

Image decode_png(const std::vector<uint8_t>& bytes, const std::string& name) {
    if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0) throw_bad_input(name, "not a PNG file");
    PngError err;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &err, on_png_error, on_png_warning);
    if (!png) throw std::bad_alloc();
    png_infop info = png_create_info_struct(png);
    Image im;
    std::vector<png_bytep> row_pointers;
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        throw_bad_input(name, "broken PNG: " + err.message);
    }
    ReadCursor cursor{&bytes, 0};
    png_set_read_fn(png, &cursor, read_bytes);
    png_set_user_limits(png, 16384, 16384);
    png_read_info(png, info);
    png_set_expand(png);       // palette and low-bit grey to 8 bit, tRNS to alpha
    png_set_strip_16(png);
    png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    im.width = int(png_get_image_width(png, info));
    im.height = int(png_get_image_height(png, info));
    if (png_get_rowbytes(png, info) != size_t(im.width) * 4) png_error(png, "unexpected row layout");
    im.rgba.resize(size_t(im.width) * size_t(im.height) * 4);
    row_pointers.resize(size_t(im.height));
    for (int y = 0; y < im.height; ++y) row_pointers[size_t(y)] = im.rgba.data() + size_t(y) * size_t(im.width) * 4;
    png_read_image(png, row_pointers.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    return im;
}

void write_png(const Image& image, const std::string& path) {
    const std::vector<uint8_t> bytes = encode_png(image);
    // Written beside the target and renamed over it, so a reader (a golden test
    // running while baselines are updated, a viewer) never sees half a file.
    const std::string tmp = path + ".tmp" + std::to_string(::getpid());
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) throw Error(ErrorKind::CannotWrite, path + ": cannot write: " + std::strerror(errno));
    bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    int saved = errno;
    if (std::fclose(f) != 0 && ok) ok = false, saved = errno;
    if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) ok = false, saved = errno;
    if (!ok) {
        std::remove(tmp.c_str());
        throw Error(ErrorKind::CannotWrite, path + ": cannot write: " + std::strerror(saved));
    }
}

Image read_png(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw_bad_input(path, std::string("cannot open: ") + std::strerror(errno));
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return decode_png(bytes, path);
}

std::string CompareResult::summary() const {
    std::ostringstream s;
    if (!same_size) {
        s << "sizes differ: " << actual_width << "x" << actual_height << " against " << expected_width << "x"
          << expected_height;
        return s.str();
    }
    s << differing_pixels << " pixels differ (" << differing_fraction * 100.0 << "%), largest channel difference "
      << max_channel_difference;
    return s.str();
}

CompareResult compare_images(const Image& actual, const Image& expected, const CompareOptions& options) {
    CompareResult r;
    r.actual_width = actual.width, r.actual_height = actual.height;
    r.expected_width = expected.width, r.expected_height = expected.height;
    r.same_size = actual.width == expected.width && actual.height == expected.height &&
                  actual.rgba.size() == expected.rgba.size();
    if (!r.same_size) {
        r.differing_fraction = 1.0;
        return r;
    }
    r.diff = Image::filled(expected.width, expected.height, 0, 0, 0);
    const size_t n = size_t(expected.width) * size_t(expected.height);
    for (size_t p = 0; p < n; ++p) {
        const uint8_t* a = &actual.rgba[p * 4];
        const uint8_t* e = &expected.rgba[p * 4];
        int worst = 0;
        for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int(a[c]) - int(e[c])));
        r.max_channel_difference = std::max(r.max_channel_difference, worst);
        uint8_t* d = &r.diff.rgba[p * 4];
        if (worst > options.channel_threshold) {
            ++r.differing_pixels;
            d[0] = 255, d[1] = 0, d[2] = 0;
        } else {
            // Faded expected image, so the red marks can be placed on the picture.
            const int grey = (int(e[0]) * 3 + int(e[1]) * 6 + int(e[2])) / 10;
            d[0] = d[1] = d[2] = uint8_t(160 + grey * 95 / 255);
        }
    }
    r.differing_fraction = n ? double(r.differing_pixels) / double(n) : 0.0;
    r.passed = r.differing_fraction <= options.max_differing_fraction;
    return r;
}

} // namespace spt::render
