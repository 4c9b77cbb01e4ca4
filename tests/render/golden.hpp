#pragma once
// Golden-image checks: compare a render with resources/golden/NAME.png.
// On failure the actual image and a diff image go to BUILD/test-output/golden/.
// SPT_UPDATE_GOLDEN=1 rewrites the baselines instead (docs/rendering.md).
#include "spt/render/image.hpp"
#include <gtest/gtest.h>
#include <string>

namespace spt::test {

// Baseline path of a golden image.
std::string golden_path(const std::string& name);
// Directory for actual and diff images of failed comparisons.
std::string golden_output_dir();
// True when SPT_UPDATE_GOLDEN=1 asks to rewrite baselines.
bool golden_update_requested();

struct GoldenOutcome {
    bool passed = false;
    bool updated = false;     // the baseline was (re)written
    std::string message;      // what happened, with file paths
    std::string actual_path;  // written on failure
    std::string diff_path;    // written on failure when sizes match
};

// Compares `image` with the baseline `name`. With allow_update and
// SPT_UPDATE_GOLDEN=1 the baseline is rewritten and the check passes.
GoldenOutcome check_golden(const render::Image& image, const std::string& name, bool allow_update = true,
                           const render::CompareOptions& options = {});

} // namespace spt::test

// Expects `image` to match the golden image `name`; prints where the evidence went.
#define EXPECT_GOLDEN(image, name)                                               \
    do {                                                                         \
        const ::spt::test::GoldenOutcome golden_outcome_ = ::spt::test::check_golden((image), (name)); \
        if (golden_outcome_.updated) std::cout << golden_outcome_.message << "\n"; \
        EXPECT_TRUE(golden_outcome_.passed) << golden_outcome_.message;          \
    } while (0)
