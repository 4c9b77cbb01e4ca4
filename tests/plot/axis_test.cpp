// Axis ranges, ticks and fractions, checked against values worked out by hand.
#include "spt/plot/axis.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace spt::plot;

namespace {

Axis log_axis() {
    Axis a;
    a.scale = Scale::Log10;
    return a;
}

} // namespace

TEST(axis, log_range_rounds_out_to_whole_decades) {
    const Range r = resolve_range(log_axis(), 150, 2.3e6);
    EXPECT_DOUBLE_EQ(r.lo, 100);
    EXPECT_DOUBLE_EQ(r.hi, 1e7);
}

TEST(axis, log_ticks_fall_on_every_decade_evenly_spaced) {
    const Axis a = log_axis();
    const Range r{100, 1e7};
    const auto ticks = axis_ticks(a, r);
    ASSERT_EQ(ticks.size(), 6u);
    for (size_t i = 0; i < ticks.size(); ++i) {
        EXPECT_DOUBLE_EQ(ticks[i].value, std::pow(10.0, 2 + double(i)));
        EXPECT_NEAR(axis_fraction(Scale::Log10, r, ticks[i].value), double(i) / 5, 1e-12);
    }
    // Halfway across 10^2..10^7 in log terms is 10^4.5, the geometric mean of 10^4 and 10^5.
    EXPECT_NEAR(axis_fraction(Scale::Log10, r, std::sqrt(1e4 * 1e5)), 0.5, 1e-12);
}

TEST(axis, log_ticks_thin_out_over_many_decades) {
    const auto ticks = axis_ticks(log_axis(), Range{1e-30, 1e30});
    EXPECT_LE(ticks.size(), 13u);
    EXPECT_GE(ticks.size(), 5u);
}

TEST(axis, log_tick_labels_use_the_axis_format) {
    Axis a = log_axis();
    a.format = [](double v) { return QString("<%1>").arg(std::log10(v)); };
    const auto ticks = axis_ticks(a, Range{10, 1000});
    ASSERT_EQ(ticks.size(), 3u);
    EXPECT_EQ(ticks[0].label, "<1>");
    EXPECT_EQ(ticks[2].label, "<3>");
}

TEST(axis, linear_ticks_are_multiples_of_the_given_step) {
    Axis a;
    a.step = 10;
    const auto ticks = axis_ticks(a, Range{45, 100.5});
    ASSERT_EQ(ticks.size(), 6u);
    EXPECT_DOUBLE_EQ(ticks.front().value, 50);
    EXPECT_DOUBLE_EQ(ticks.back().value, 100);
    EXPECT_EQ(ticks.back().label, "100");
}

TEST(axis, automatic_linear_step_is_one_two_or_five_times_a_power_of_ten) {
    Axis a;
    for (const Range r : {Range{0, 1}, Range{-3, 17}, Range{0.001, 0.0047}, Range{1e6, 7.3e6}}) {
        const auto ticks = axis_ticks(a, r);
        ASSERT_GE(ticks.size(), 3u);
        ASSERT_LE(ticks.size(), 12u);
        const double step = ticks[1].value - ticks[0].value;
        const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
        EXPECT_TRUE(std::abs(mantissa - 1) < 1e-6 || std::abs(mantissa - 2) < 1e-6 || std::abs(mantissa - 5) < 1e-6)
            << "step " << step;
    }
}

TEST(axis, zero_tick_is_not_negative_zero) {
    Axis a;
    a.step = 0.1;
    for (const Tick& t : axis_ticks(a, Range{-0.3, 0.3})) {
        if (t.value == 0) {
            EXPECT_EQ(t.label, "0");
        }
    }
}

TEST(axis, step_too_fine_for_the_range_falls_back_to_automatic) {
    Axis a;
    a.step = 1e-12;
    EXPECT_LE(axis_ticks(a, Range{0, 1}).size(), 12u);
}

TEST(axis, explicit_ticks_outside_the_range_or_unplottable_are_dropped) {
    Axis a = log_axis();
    a.ticks = {{0.5, "a"}, {5, "b"}, {50, "c"}, {-1, "d"}, {NAN, "e"}};
    const auto ticks = axis_ticks(a, Range{1, 10});
    ASSERT_EQ(ticks.size(), 1u);
    EXPECT_EQ(ticks[0].label, "b");
}

TEST(axis, fixed_ends_are_kept_whatever_the_data) {
    Axis a;
    a.min = 3, a.max = 7;
    const Range r = resolve_range(a, 0, 100);
    EXPECT_EQ(r.lo, 3);
    EXPECT_EQ(r.hi, 7);
}

TEST(axis, one_fixed_end_and_data_beyond_it_still_gives_a_range) {
    Axis a;
    a.min = 50;
    const Range r = resolve_range(a, 0, 40);
    EXPECT_EQ(r.lo, 50);
    EXPECT_GT(r.hi, r.lo);
    Axis b;
    b.scale = Scale::Log10, b.max = 10;
    const Range l = resolve_range(b, 100, 1000);
    EXPECT_EQ(l.hi, 10);
    EXPECT_GT(l.lo, 0);
    EXPECT_LT(l.lo, l.hi);
}

TEST(axis, single_value_is_centred_in_a_range_of_its_own) {
    Axis lin;
    const Range r = resolve_range(lin, 50, 50);
    EXPECT_LT(r.lo, 50);
    EXPECT_GT(r.hi, 50);
    const Range z = resolve_range(lin, 0, 0);
    EXPECT_LT(z.lo, 0);
    EXPECT_GT(z.hi, 0);
    const Range l = resolve_range(log_axis(), 1000, 1000);
    EXPECT_LT(l.lo, 1000);
    EXPECT_GT(l.hi, 1000);
}

TEST(axis, no_data_gives_a_default_range) {
    const Range r = resolve_range(Axis{}, 1, 0);
    EXPECT_LT(r.lo, r.hi);
    const Range l = resolve_range(log_axis(), INFINITY, -INFINITY);
    EXPECT_GT(l.lo, 0);
    EXPECT_LT(l.lo, l.hi);
}

TEST(axis, unplottable_fixed_end_on_a_log_axis_is_ignored) {
    Axis a = log_axis();
    a.min = 0;
    const Range r = resolve_range(a, 20, 300);
    EXPECT_DOUBLE_EQ(r.lo, 10);
    EXPECT_DOUBLE_EQ(r.hi, 1000);
}

TEST(axis, fraction_of_an_unplottable_value_is_nan) {
    const Range r{1, 10};
    EXPECT_TRUE(std::isnan(axis_fraction(Scale::Linear, r, NAN)));
    EXPECT_TRUE(std::isnan(axis_fraction(Scale::Linear, r, INFINITY)));
    EXPECT_TRUE(std::isnan(axis_fraction(Scale::Log10, r, 0)));
    EXPECT_TRUE(std::isnan(axis_fraction(Scale::Log10, r, -5)));
    EXPECT_DOUBLE_EQ(axis_fraction(Scale::Linear, r, 5.5), 0.5);
}
