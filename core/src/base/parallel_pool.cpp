// The library's pool: one oneTBB arena, made at the first parallel call, whose threads are
// oneTBB's (shared with a host that uses oneTBB too). No global setting is changed.
#include "base/parallel.hpp"
#include <atomic>
#include <memory>
#include <mutex>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

namespace spt::detail {
namespace {

std::atomic<bool> started{false};

tbb::task_arena& arena() {
    // Never destroyed: a thread the host left running at exit may still be inside it.
    static tbb::task_arena* a = [] {
        auto* made = new tbb::task_arena(tbb::task_arena::automatic);
        started.store(true);
        return made;
    }();
    return *a;
}

} // namespace

bool pool_started() { return started.load(); }

void run_jobs(int count, TaskSystem* tasks, const std::function<void(int)>& job) {
    if (count <= 1) {
        if (count == 1) job(0);
        return;
    }
    if (tasks) {
        tasks->run(count, job);
        return;
    }
    // The call's own jobs only while it waits (isolate): a thread waiting inside a job for nested
    // work must not pick up a sibling job of an outer call, which could wait on the suspended one.
    arena().execute([&] {
        tbb::this_task_arena::isolate([&] {
            tbb::task_group group;
            for (int w = 1; w < count; ++w) group.run([&job, w] { job(w); });
            job(0);
            group.wait();
        });
    });
}

} // namespace spt::detail

namespace spt {

void run_parallel(int count, const std::function<void(int)>& job, TaskSystem* tasks) {
    if (count <= 0) return;
    detail::parallel_for(size_t(count), count, [&job](size_t k, int) { job(int(k)); }, tasks);
}

int hardware_threads() { return int(std::max(1u, std::thread::hardware_concurrency())); }

} // namespace spt
