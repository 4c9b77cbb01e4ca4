// detail::parallel_for: every item once, on any number of threads, and exceptions that reach the caller;
// detail::parallel_levels: how deep a recursion hands subtrees to threads.
#include "base/parallel.hpp"
#include <atomic>
#include <gtest/gtest.h>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

using spt::detail::parallel_for;

namespace {

TEST(ParallelFor, EveryItemRunsOnceOnEveryThreadCount) {
    for (int threads : {1, 2, 3, 8}) {
        std::vector<std::atomic<int>> runs(1000);
        parallel_for(runs.size(), threads, [&](size_t i, int worker) {
            EXPECT_GE(worker, 0);
            EXPECT_LT(worker, threads);
            ++runs[i];
        });
        for (size_t i = 0; i < runs.size(); ++i) ASSERT_EQ(runs[i].load(), 1) << "item " << i << ", " << threads << " threads";
    }
}

TEST(ParallelFor, AnExceptionOnAWorkerReachesTheCallerWithItsTypeAndMessage) {
    for (int threads : {1, 2, 4}) {
        try {
            parallel_for(1000, threads, [](size_t i, int) {
                if (i == 377) throw std::runtime_error("item 377 refused");
            });
            FAIL() << "no exception with " << threads << " threads";
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()), "item 377 refused");
        }
        EXPECT_THROW(parallel_for(64, threads, [](size_t i, int) { if (i % 7 == 3) throw std::bad_alloc(); }), std::bad_alloc);
    }
}

} // namespace

TEST(ParallelLevels, NoneOnOneThreadAndOneMoreThanTheDoublingsAbove) {
    EXPECT_EQ(spt::detail::parallel_levels(0), 0);
    EXPECT_EQ(spt::detail::parallel_levels(1), 0);
    EXPECT_EQ(spt::detail::parallel_levels(2), 2); // four subtrees on two threads
    EXPECT_EQ(spt::detail::parallel_levels(3), 3);
    EXPECT_EQ(spt::detail::parallel_levels(4), 3);
    EXPECT_EQ(spt::detail::parallel_levels(8), 4);
}
