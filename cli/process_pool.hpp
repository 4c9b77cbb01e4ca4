#pragma once
// Runs jobs in forked child processes, a few at a time. A job that crashes (assimp
// has crashed on some files), hangs or runs out of memory takes down only itself.
#include <cstddef>
#include <functional>
#include <string>

namespace spt::cli {

/// How one job ended.
struct JobOutcome {
    int exit_code = 0;      ///< the job's return value, or 2 if it crashed or timed out
    std::string messages;   ///< everything the job wrote to stderr
    std::string abnormal;   ///< empty, or why the job did not finish normally
    double seconds = 0;     ///< wall time
};

/// Runs work(i) for i in [0, n) with at most `jobs` children at once. `done` is called in
/// the parent, in completion order. timeout_s <= 0 means no limit. memory_limit_bytes 0: none.
void run_in_processes(size_t n, int jobs, double timeout_s, size_t memory_limit_bytes,
                      const std::function<int(size_t)>& work,
                      const std::function<void(size_t, const JobOutcome&)>& done);

} // namespace spt::cli
