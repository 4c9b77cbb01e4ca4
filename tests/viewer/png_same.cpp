// png_same A.png B.png: exit 0 if the two pictures look the same by the goldens' rule
// (render::compare_images, colour only), 1 with the difference otherwise. For shell tests.
#include "spt/render/image.hpp"
#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: png_same A.png B.png\n");
        return 2;
    }
    try {
        spt::render::Image a = spt::render::read_png(argv[1]), b = spt::render::read_png(argv[2]);
        for (auto* image : {&a, &b})
            for (size_t k = 3; k < image->rgba.size(); k += 4) image->rgba[k] = 255;
        const spt::render::CompareResult r = spt::render::compare_images(a, b);
        std::printf("%s\n", r.summary().c_str());
        return r.passed ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "png_same: %s\n", e.what());
        return 2;
    }
}
