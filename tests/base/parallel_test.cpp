// detail::parallel_for: every item once, on any number of threads and on a host's task system,
// exceptions that reach the caller, nested calls, items waiting on earlier ones, and no pool for
// work on 1 thread; detail::parallel_levels: how deep a recursion hands subtrees to threads.
#include "base/parallel.hpp"
#include "host_task_system.hpp"
#include <atomic>
#include <cstdlib>
#include <gtest/gtest.h>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

using spt::detail::parallel_for;
using spt::test::HostTaskSystem;

namespace {

TEST(ParallelFor, EveryItemRunsOnceOnEveryThreadCountAndNeverTwoAtOnceOnOneWorker) {
    HostTaskSystem host(3);
    for (spt::TaskSystem* tasks : {static_cast<spt::TaskSystem*>(nullptr), static_cast<spt::TaskSystem*>(&host)})
        for (int threads : {1, 2, 3, 8}) {
            std::vector<std::atomic<int>> runs(1000);
            std::vector<std::atomic<bool>> busy(static_cast<size_t>(threads)); // per-worker scratch stands for this
            parallel_for(runs.size(), threads, [&](size_t i, int worker) {
                ASSERT_GE(worker, 0);
                ASSERT_LT(worker, threads);
                EXPECT_FALSE(busy[size_t(worker)].exchange(true)) << "worker " << worker << " shared";
                ++runs[i];
                busy[size_t(worker)].store(false);
            }, tasks);
            for (size_t i = 0; i < runs.size(); ++i)
                ASSERT_EQ(runs[i].load(), 1) << "item " << i << ", " << threads << " threads, host " << bool(tasks);
        }
    EXPECT_GT(host.runs.load(), 0) << "the host's task system was not used";
}

TEST(ParallelFor, AnExceptionOnAWorkerReachesTheCallerWithItsTypeAndMessage) {
    HostTaskSystem host(3);
    for (spt::TaskSystem* tasks : {static_cast<spt::TaskSystem*>(nullptr), static_cast<spt::TaskSystem*>(&host)})
        for (int threads : {1, 2, 4}) {
            try {
                parallel_for(1000, threads, [](size_t i, int) {
                    if (i == 377) throw std::runtime_error("item 377 refused");
                }, tasks);
                FAIL() << "no exception with " << threads << " threads";
            } catch (const std::runtime_error& e) {
                EXPECT_EQ(std::string(e.what()), "item 377 refused");
            }
            EXPECT_THROW(parallel_for(64, threads, [](size_t i, int) { if (i % 7 == 3) throw std::bad_alloc(); }, tasks),
                         std::bad_alloc);
        }
}

// A recursion that hands its second half to another thread at every level, as the tree builder
// does: each level waits inside a job for its own nested jobs.
size_t nested_leaves(int depth, spt::TaskSystem* tasks) {
    if (depth == 0) return 1;
    size_t sub[2] = {0, 0};
    parallel_for(2, 2, [&](size_t k, int) { sub[k] = nested_leaves(depth - 1, tasks); }, tasks);
    return sub[0] + sub[1];
}

TEST(ParallelFor, NestedCallsFinishOnThePoolAndOnAHostsTasks) {
    HostTaskSystem host(2);
    for (spt::TaskSystem* tasks : {static_cast<spt::TaskSystem*>(nullptr), static_cast<spt::TaskSystem*>(&host)}) {
        std::vector<size_t> leaves(16);
        parallel_for(leaves.size(), 4, [&](size_t i, int) { leaves[i] = nested_leaves(7, tasks); }, tasks);
        for (size_t l : leaves) EXPECT_EQ(l, 128u);
    }
}

// The response's pattern: an item waits for an earlier one, which a job took before it.
TEST(ParallelFor, AnItemMayWaitForAnEarlierOne) {
    HostTaskSystem host(3);
    for (spt::TaskSystem* tasks : {static_cast<spt::TaskSystem*>(nullptr), static_cast<spt::TaskSystem*>(&host)})
        for (int threads : {2, 4, 8}) {
            std::vector<std::atomic<bool>> done(500);
            parallel_for(done.size(), threads, [&](size_t i, int) {
                while (i > 0 && !done[i - 1].load()) std::this_thread::yield();
                done[i].store(true);
            }, tasks);
            EXPECT_TRUE(done.back().load());
        }
}

// In a process of its own (the pool is made once a process): work on 1 thread, or of fewer than
// two items, or on a host's task system never makes the pool; work on 2 threads does.
TEST(ParallelFor, ThePoolIsMadeOnlyByWorkOnTwoThreadsOrMore) {
    testing::GTEST_FLAG(death_test_style) = "threadsafe";
    EXPECT_EXIT(
        {
            std::atomic<int> sum{0};
            parallel_for(100, 1, [&](size_t, int) { ++sum; });
            parallel_for(1, 8, [&](size_t, int) { ++sum; });
            {
                HostTaskSystem host(2);
                parallel_for(100, 4, [&](size_t, int) { ++sum; }, &host);
            }
            if (spt::detail::pool_started() || sum != 201) std::exit(1);
            parallel_for(100, 2, [&](size_t, int) { ++sum; });
            std::exit(spt::detail::pool_started() && sum == 301 ? 0 : 2);
        },
        testing::ExitedWithCode(0), "");
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
