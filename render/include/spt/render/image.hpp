#pragma once
/// RGBA8 images, PNG files and the image comparison the golden tests use.
#include <cstdint>
#include <string>
#include <vector>

namespace spt::render {

/// An 8-bit RGBA image; row 0 is the top row (not GL's bottom row), rows are tightly packed.
struct Image {
    int width = 0;  ///< pixels
    int height = 0; ///< pixels
    std::vector<uint8_t> rgba; ///< width * height * 4 bytes: R, G, B, A per pixel, top row first

    /// A width x height image (pixels) filled with one colour (channels 0-255).
    static Image filled(int width, int height, uint8_t r, uint8_t g, uint8_t b, uint8_t a = 255);
    /// Pointer to pixel (x, y), x from the left, y from the top.
    uint8_t* pixel(int x, int y) { return rgba.data() + (size_t(y) * size_t(width) + size_t(x)) * 4; }
    /// Pointer to pixel (x, y), x from the left, y from the top.
    const uint8_t* pixel(int x, int y) const { return rgba.data() + (size_t(y) * size_t(width) + size_t(x)) * 4; }
};

/// Encodes as PNG bytes: RGB when every pixel is opaque, else RGBA; no timestamp or
/// other varying chunk, fixed zlib settings, so equal images give equal bytes.
std::vector<uint8_t> encode_png(const Image& image);
/// Decodes PNG bytes of any colour type and bit depth to RGBA8; throws
/// Error(BadInput) "name: problem" on anything that is not a readable PNG.
Image decode_png(const std::vector<uint8_t>& bytes, const std::string& name = "");
/// Writes encode_png(image) to `path` atomically (temporary file, then rename);
/// throws Error(CannotWrite) naming the path.
void write_png(const Image& image, const std::string& path);
/// Reads a PNG file as decode_png does; throws Error(BadInput) naming the file.
Image read_png(const std::string& path);

/// How two images may differ and still count as equal.
struct CompareOptions {
    int channel_threshold = 5;          ///< a pixel differs when some channel differs by more than this (0-255)
    double max_differing_fraction = 0.001; ///< largest fraction of differing pixels that still passes
};

/// Outcome of compare_images. When the sizes differ only the sizes are filled in.
struct CompareResult {
    bool same_size = false;       ///< both images have the same width and height
    int actual_width = 0;         ///< pixels
    int actual_height = 0;        ///< pixels
    int expected_width = 0;       ///< pixels
    int expected_height = 0;      ///< pixels
    size_t differing_pixels = 0;  ///< pixels with a channel difference above the threshold
    double differing_fraction = 0;///< differing_pixels / pixel count (1 when sizes differ)
    int max_channel_difference = 0; ///< largest difference of one channel (R, G, B or A) over all pixels, 0-255
    bool passed = false;          ///< same size and differing_fraction <= the allowed fraction
    Image diff;                   ///< expected faded to grey, differing pixels in red (empty if sizes differ)

    /// One line for test output: sizes or counts, fraction, largest difference.
    std::string summary() const;
};

/// Compares `actual` against `expected` pixel by pixel with `options`.
CompareResult compare_images(const Image& actual, const Image& expected, const CompareOptions& options = {});

} // namespace spt::render
