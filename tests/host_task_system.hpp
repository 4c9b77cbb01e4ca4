#pragma once
// A host's task system for tests: its own std::threads and one queue of jobs, as a game engine's
// would be. A thread waiting in run() runs queued jobs meanwhile, so nested calls cannot deadlock.
#include "spt/task_system.hpp"
#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

namespace spt::test {

class HostTaskSystem final : public TaskSystem {
public:
    explicit HostTaskSystem(int threads) {
        for (int i = 0; i < threads; ++i) threads_.emplace_back([this] { serve(); });
    }
    ~HostTaskSystem() override {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        for (std::thread& t : threads_) t.join();
    }

    void run(int count, const std::function<void(int)>& job) override {
        runs.fetch_add(1);
        std::atomic<int> left{count};
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            for (int w = 0; w < count; ++w) queue_.push_back({&job, w, &left});
        }
        wake_.notify_all();
        std::unique_lock<std::mutex> lock(mutex_);
        while (left.load() > 0) {
            if (!queue_.empty()) {
                run_front(lock);
            } else {
                wake_.wait(lock);
            }
        }
    }

    std::atomic<int> runs{0};      // calls of run()
    std::atomic<int> host_jobs{0}; // jobs run on the host's own threads

private:
    struct Item {
        const std::function<void(int)>* job;
        int w;
        std::atomic<int>* left;
    };

    // Runs the queue's first job without the lock; returns with it held again.
    void run_front(std::unique_lock<std::mutex>& lock) {
        const Item it = queue_.front();
        queue_.pop_front();
        lock.unlock();
        (*it.job)(it.w);
        lock.lock();
        it.left->fetch_sub(1);
        wake_.notify_all(); // a caller may be waiting for this one
    }

    void serve() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
            if (queue_.empty()) return; // stopping, nothing left
            host_jobs.fetch_add(1);
            run_front(lock);
        }
    }

    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Item> queue_;
    bool stop_ = false;
    std::vector<std::thread> threads_;
};

} // namespace spt::test
