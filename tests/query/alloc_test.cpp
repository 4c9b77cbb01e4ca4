// Replaces global operator new to count allocations; its own test binary.
#include "query_fixtures.hpp"
#include "spt/query.hpp"
#include <gtest/gtest.h>
#include <atomic>
#include <cstdlib>
#include <new>

static std::atomic<long> g_allocations{0};

void* operator new(size_t n) {
    ++g_allocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
// GCC 12 with the sanitizers inlines these into gtest and calls the free() of memory from
// operator new mismatched, not seeing that this operator new is malloc.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace spt {
namespace {

TEST(QueryMemory, RepeatedQueriesAllocateNothingAfterTheFirst) {
    auto a = test::make_object(make_torus(1.0, 0.35, 20, 10));
    auto b = test::make_object(make_box({0.8, 0.5, 0.3}, 3));
    std::mt19937 rng(1);
    std::vector<Pose> poses;
    for (int i = 0; i < 50; ++i) poses.push_back(test::random_pose(rng, 0.8 + 0.02 * i));
    QueryScratch s;
    for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact})
        for (QueryMode mode : {QueryMode::Any, QueryMode::Deepest, QueryMode::All}) {
            QueryOptions o;
            o.level = level, o.mode = mode, o.normal_culling = mode == QueryMode::Deepest;
            for (const Pose& p : poses) collide_relative(a->model, b->model, p, o, s); // warm up
            const long before = g_allocations.load();
            int collisions = 0;
            for (const Pose& p : poses) collisions += collide_relative(a->model, b->model, p, o, s).collide;
            EXPECT_EQ(g_allocations.load() - before, 0) << "level " << int(level) << " mode " << int(mode);
            EXPECT_GT(collisions, 0);
        }
}

} // namespace
} // namespace spt
