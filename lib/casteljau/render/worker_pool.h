// WorkerPool: threads kept from one frame to the next.
//
// A frame on n threads needs n - 1 helpers. Starting and joining one costs
// 42-47 us on the 2-core machine of bench/README.md, a tenth of a small
// frame on two threads (the ellipse scene takes 0.4-0.6 ms), paid again by
// every partial redraw; a run of this pool on two threads costs 6-8 us
// (an empty job, 2000 runs). The helpers wait on a condition variable
// between runs, so an idle pool takes no CPU time.
//
// run(n, job) calls job(0) on the calling thread and job(1) ... job(n - 1)
// on the pool's threads, and returns when every call has returned. The pool
// grows to the largest n asked of it; its threads end with it. One run at a
// time: run is not reentrant and not for concurrent callers.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace casteljau {

/// Threads that wait between runs of a job split into n parts.
class WorkerPool {
  public:
    WorkerPool() = default;
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;
    /// Wakes the threads to end, and joins them.
    ~WorkerPool();

    /// Calls job(t) for t in [0, n): t = 0 on this thread, the others on the
    /// pool's; returns when all have returned. `job` is called as `job(int)`.
    template <class Job>
    void run(int n, const Job& job) {
        run_erased(n, &call_job<Job>, &job);
    }

  private:
    // Type-erased by hand: a std::function of a lambda with several captures
    // would allocate on every frame.
    using Call = void (*)(const void* job, int part);
    template <class Job>
    static void call_job(const void* job, int part) {
        (*static_cast<const Job*>(job))(part);
    }
    void run_erased(int n, Call call, const void* job);
    /// The loop of the thread that runs part `part` of each job.
    void serve(int part, std::uint64_t seen);

    std::vector<std::thread> threads_; ///< threads_[i] runs part i + 1
    std::mutex mutex_;
    std::condition_variable wake_; ///< a new run, or the end
    std::condition_variable done_; ///< the last helper of a run has returned
    Call call_ = nullptr;
    const void* job_ = nullptr;
    std::uint64_t generation_ = 0; ///< runs started; a helper waits for the next
    int parts_ = 0;                ///< parts of the current run
    int running_ = 0;              ///< helpers of the current run still working
    bool stop_ = false;
};

} // namespace casteljau
