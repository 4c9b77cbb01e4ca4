// The distances' best-first order (core/src/query/best_first.hpp): carrying the least child past
// the heap must hand back the same pairs in the same order as pushing it and popping.
#include "query/best_first.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <functional>
#include <random>

namespace spt {
namespace {

TEST(BestFirst, CarryingTheLeastChildTakesThePairsInTheHeapsOwnOrder) {
    using Bound = detail::ScratchBuffers::GapBoundOf<float>;
    std::mt19937 rng(5);
    // Few distinct gaps, so that ties (told by the indices) are common.
    std::uniform_int_distribution<int> gap(0, 40), kids(0, 2);
    int carried = 0; // over every run: the carry is taken, not only the heap
    for (int run = 0; run < 200; ++run) {
        std::vector<Bound> room, plain;
        detail::BestFirst<float> order(room);
        uint32_t next_id = 1;
        order.push(0, 0, 0);
        plain.push_back({0, 0, 0});
        for (int step = 0; step < 300; ++step) {
            Bound got, want;
            const bool have = order.take(got);
            ASSERT_EQ(have, !plain.empty());
            if (!have) break;
            std::pop_heap(plain.begin(), plain.end(), std::greater<Bound>());
            want = plain.back();
            plain.pop_back();
            ASSERT_EQ(got.gap, want.gap);
            ASSERT_EQ(got.a, want.a);
            ASSERT_EQ(got.b, want.b);
            // Children lie no nearer than their parent, as lower bounds down a tree do; often as
            // near, so that a child comes before the heap's front and is carried.
            Bound children[2];
            const int n = kids(rng) == 0 && rng() % 3 == 0 ? 0 : 1 + int(rng() % 2); // a pair is pruned now and then
            for (int k = 0; k < n; ++k) {
                children[k] = {got.gap + (rng() % 2 ? 0.0f : float(gap(rng))), next_id, uint32_t(rng() % 7)};
                next_id += 1;
                plain.push_back(children[k]);
                std::push_heap(plain.begin(), plain.end(), std::greater<Bound>());
            }
            const size_t before = room.size();
            order.push_children(children, n);
            carried += n > 0 && room.size() < before + size_t(n);
        }
    }
    EXPECT_GT(carried, 1000);
}

} // namespace
} // namespace spt
