// PNG round trips and byte stability, bad files and paths, and the image comparison's thresholds.
#include "spt/error.hpp"
#include "spt/render/image.hpp"
#include <filesystem>
#include <gtest/gtest.h>

using namespace spt::render;

namespace {

Image gradient(int w, int h, bool alpha) {
    Image im = Image::filled(w, h, 0, 0, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            uint8_t* p = im.pixel(x, y);
            p[0] = uint8_t(x * 7), p[1] = uint8_t(y * 5), p[2] = uint8_t(x ^ y), p[3] = alpha ? uint8_t(x + y) : 255;
        }
    return im;
}

std::string temp_dir() {
    const std::string d = std::string(SPT_BINARY_DIR) + "/test-output/image";
    std::filesystem::create_directories(d);
    return d;
}

} // namespace

TEST(image, png_round_trip_keeps_every_pixel) {
    for (bool alpha : {false, true}) {
        const Image a = gradient(37, 23, alpha);
        const Image b = decode_png(encode_png(a));
        EXPECT_EQ(b.width, 37);
        EXPECT_EQ(b.height, 23);
        EXPECT_EQ(a.rgba, b.rgba) << "alpha " << alpha;
    }
}

TEST(image, png_bytes_are_the_same_every_time) {
    const Image a = gradient(64, 64, false);
    EXPECT_EQ(encode_png(a), encode_png(a));
}

TEST(image, file_round_trip) {
    const std::string path = temp_dir() + "/round_trip.png";
    const Image a = gradient(16, 9, false);
    write_png(a, path);
    EXPECT_EQ(read_png(path).rgba, a.rgba);
}

TEST(image, broken_png_is_bad_input_naming_the_file) {
    try {
        decode_png({'n', 'o', 't', ' ', 'a', ' ', 'p', 'n', 'g'}, "x.png");
        FAIL() << "no error";
    } catch (const spt::Error& e) {
        EXPECT_EQ(e.kind(), spt::ErrorKind::BadInput);
        EXPECT_NE(std::string(e.what()).find("x.png"), std::string::npos) << e.what();
    }
    std::vector<uint8_t> bytes = encode_png(gradient(32, 32, false));
    bytes.resize(bytes.size() / 2);
    EXPECT_THROW(decode_png(bytes, "half.png"), spt::Error);
    try {
        read_png(temp_dir() + "/does_not_exist.png");
        FAIL() << "no error";
    } catch (const spt::Error& e) {
        EXPECT_EQ(e.kind(), spt::ErrorKind::BadInput);
        EXPECT_NE(std::string(e.what()).find("does_not_exist.png"), std::string::npos);
    }
}

TEST(image, unwritable_path_is_cannot_write) {
    try {
        write_png(gradient(4, 4, false), temp_dir() + "/no/such/dir/out.png");
        FAIL() << "no error";
    } catch (const spt::Error& e) {
        EXPECT_EQ(e.kind(), spt::ErrorKind::CannotWrite);
        EXPECT_NE(std::string(e.what()).find("out.png"), std::string::npos);
    }
}

TEST(image, compare_channel_threshold_is_exclusive) {
    const Image a = Image::filled(10, 10, 100, 100, 100);
    Image b = a;
    b.pixel(3, 4)[2] = 105; // difference 5: equal
    CompareResult r = compare_images(b, a, {5, 0.0});
    EXPECT_TRUE(r.passed);
    EXPECT_EQ(r.differing_pixels, 0u);
    EXPECT_EQ(r.max_channel_difference, 5);
    b.pixel(3, 4)[2] = 106; // difference 6: differs
    r = compare_images(b, a, {5, 0.0});
    EXPECT_FALSE(r.passed);
    EXPECT_EQ(r.differing_pixels, 1u);
    // The diff image marks exactly that pixel in red.
    const uint8_t* d = r.diff.pixel(3, 4);
    EXPECT_EQ(d[0], 255);
    EXPECT_EQ(d[1], 0);
    EXPECT_NE(r.diff.pixel(4, 4)[1], 0);
}

TEST(image, compare_fraction_limit) {
    const Image a = Image::filled(100, 100, 0, 0, 0);
    Image b = a;
    for (int i = 0; i < 10; ++i) b.pixel(i, 0)[0] = 200; // 10 of 10000 = 0.1%
    EXPECT_TRUE(compare_images(b, a).passed);
    b.pixel(10, 0)[0] = 200; // 0.11%
    const CompareResult r = compare_images(b, a);
    EXPECT_FALSE(r.passed);
    EXPECT_NEAR(r.differing_fraction, 0.0011, 1e-12);
}

TEST(image, compare_different_sizes_fails) {
    const CompareResult r = compare_images(Image::filled(4, 4, 0, 0, 0), Image::filled(4, 5, 0, 0, 0));
    EXPECT_FALSE(r.same_size);
    EXPECT_FALSE(r.passed);
    EXPECT_EQ(r.summary(), "sizes differ: 4x4 against 4x5");
}
