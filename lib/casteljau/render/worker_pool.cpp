#include "casteljau/render/worker_pool.h"

namespace casteljau {

WorkerPool::~WorkerPool() {
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void WorkerPool::run_erased(int n, Call call, const void* job) {
    if (n > 1) {
        {
            const std::lock_guard lock(mutex_);
            // A new thread has seen every run before this one.
            while (int(threads_.size()) < n - 1)
                threads_.emplace_back(&WorkerPool::serve, this, int(threads_.size()) + 1,
                                      generation_);
            call_ = call, job_ = job;
            parts_ = n, running_ = n - 1;
            ++generation_;
        }
        wake_.notify_all();
    }
    call(job, 0);
    if (n > 1) {
        std::unique_lock lock(mutex_);
        done_.wait(lock, [&] { return running_ == 0; });
    }
}

void WorkerPool::serve(int part, std::uint64_t seen) {
    for (;;) {
        Call call;
        const void* job;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
            if (stop_) return;
            seen = generation_;
            // A run with fewer parts leaves this thread waiting; a run needing
            // it cannot end before it has run, so it never misses one.
            if (part >= parts_) continue;
            call = call_, job = job_;
        }
        call(job, part);
        const std::lock_guard lock(mutex_);
        if (--running_ == 0) done_.notify_one();
    }
}

} // namespace casteljau
