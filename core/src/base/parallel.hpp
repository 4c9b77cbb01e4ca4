#pragma once
// Runs f(i, worker) for i in [0, n) on up to `threads` threads. Results must be written
// per i so that the outcome does not depend on which worker ran which i.
#include "spt/task_system.hpp"
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace spt::detail {

// Calls job(w) for every w in [0, count) on the host's `tasks`, or, when null, on the library's
// pool (oneTBB, made at the first call; parallel_pool.cpp), and returns when all have returned.
// The calling thread runs jobs too. job must not throw.
void run_jobs(int count, TaskSystem* tasks, const std::function<void(int)>& job);

// Whether the library's pool has been made (tests: work on 1 thread never makes it).
bool pool_started();

/// Runs f(i, worker) for every i in [0, n) as min(threads, n) jobs, on the host's `tasks` if
/// given, else on the library's pool; worker is the job's index, < min(threads, n), and a job
/// runs one item at a time, so per-worker scratch indexed by it is never shared. An exception
/// thrown by f (out of memory, a refused input) stops the items not yet begun and is thrown
/// again on the calling thread once every job has returned, as on one thread. Items start in
/// increasing order of i (a job takes the next when it is free), so an item may wait for an
/// earlier one without a deadlock, however late a job starts.
template <class F>
void parallel_for(size_t n, int threads, F&& f, TaskSystem* tasks = nullptr) {
    if (threads <= 1 || n < 2) {
        for (size_t i = 0; i < n; ++i) f(i, 0);
        return;
    }
    std::atomic<size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto work = [&](int w) {
        try {
            for (size_t i = next.fetch_add(1); i < n; i = next.fetch_add(1)) f(i, w);
        } catch (...) {
            next.store(n); // the others take nothing more
            const std::lock_guard<std::mutex> lock(error_mutex);
            if (!error) error = std::current_exception();
        }
    };
    // One captured pointer: kept inside std::function, no allocation a call.
    run_jobs(int(std::min<size_t>(size_t(threads), n)), tasks, [&work](int w) { work(w); });
    if (error) std::rethrow_exception(error);
}

// How many levels of a binary recursion hand their second subtree to another thread so that
// `threads` threads stay busy: two subtrees a thread (an uneven split still keeps all busy).
inline int parallel_levels(int threads) {
    int levels = 0;
    for (int t = 1; t < threads; t *= 2) ++levels;
    return levels > 0 ? levels + 1 : 0;
}

// A thread count that tests pin (PinnedThreads) to show that an answer does not depend on it; 0: none.
inline int pinned_threads = 0;

// Threads for work that a caller waits on (a selection, a depth map): the machine's cores.
inline int machine_threads() {
    return pinned_threads > 0 ? pinned_threads : hardware_threads();
}

// Pins machine_threads() to `n` while it lives (tests only: the count is global).
struct PinnedThreads {
    explicit PinnedThreads(int n) : previous(pinned_threads) { pinned_threads = n; }
    ~PinnedThreads() { pinned_threads = previous; }
    PinnedThreads(const PinnedThreads&) = delete;
    PinnedThreads& operator=(const PinnedThreads&) = delete;
    int previous;
};

} // namespace spt::detail
