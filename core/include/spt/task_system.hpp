#pragma once
/// A host's own threads for the library's parallel work, as Box2D's enqueueTask and Jolt's
/// JobSystem let a host keep one set of threads for everything. Without one, the library runs
/// parallel work on its own pool (oneTBB), created at the first call that asks for 2 threads or
/// more, never for work on 1 thread. Results are the same bit for bit either way.
#include <functional>

namespace spt {

/// What a host implements to run the library's jobs on its threads.
class TaskSystem {
public:
    virtual ~TaskSystem() = default;
    /// Calls job(w) exactly once for every w in [0, count) and returns when all have returned.
    /// The calls may run concurrently, on any threads (the calling one included), in any order
    /// and as late as the host likes: each job takes the work left when it starts, so one that
    /// starts after the others have finished finds none. A job may itself call run() (a tree
    /// is built by recursion), so a thread that waits here should run queued jobs meanwhile or
    /// the host must have threads to spare. job never throws: the library catches what its
    /// work throws and rethrows it on the thread that called it.
    virtual void run(int count, const std::function<void(int)>& job) = 0;
};

/// Calls job(k) once for every k in [0, count), concurrently, on `tasks` or (when null) on the
/// library's pool, and returns when all have returned; the first exception a job throws is
/// thrown again here, once every job has stopped. For front ends' own parallel work (render/
/// splats spheres with it), so that a program keeps one set of threads.
void run_parallel(int count, const std::function<void(int)>& job, TaskSystem* tasks = nullptr);

/// Threads worth giving parallel work on this machine (a simulation, a selection, a depth map):
/// its hardware threads, at least 1.
int hardware_threads();

} // namespace spt
