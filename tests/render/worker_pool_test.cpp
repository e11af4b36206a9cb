#include "casteljau/render/worker_pool.h"

#include <array>
#include <atomic>
#include <chrono>
#include <gtest/gtest.h>
#include <random>
#include <thread>

namespace casteljau {
namespace {

// Every run calls each of its parts exactly once, part 0 on the calling
// thread and the others on other threads, and returns only after all have
// returned; across runs whose part counts grow and shrink, so that threads
// left waiting by a smaller run serve the next larger one.
TEST(WorkerPool, EachPartOnceAndAllDoneOnReturn) {
    constexpr int kMaxParts = 6;
    WorkerPool pool;
    std::mt19937 rng(17);
    const std::thread::id caller = std::this_thread::get_id();
    for (int run = 0; run < 300; ++run) {
        const int n = std::uniform_int_distribution<int>(1, kMaxParts)(rng);
        std::array<std::atomic<int>, kMaxParts> calls{};
        std::array<std::atomic<bool>, kMaxParts> on_caller{};
        const auto job = [&](int part) {
            // Some parts finish late, so that a run returning early is seen.
            if (part == run % n) std::this_thread::sleep_for(std::chrono::microseconds(200));
            on_caller[std::size_t(part)] = std::this_thread::get_id() == caller;
            ++calls[std::size_t(part)];
        };
        pool.run(n, job);
        for (int p = 0; p < kMaxParts; ++p) {
            EXPECT_EQ(calls[std::size_t(p)], p < n ? 1 : 0)
                << "run " << run << " with " << n << " parts, part " << p;
            if (p >= n) continue;
            EXPECT_EQ(on_caller[std::size_t(p)], p == 0)
                << "run " << run << " with " << n << " parts, part " << p;
        }
    }
}

// A pool whose threads were never needed again ends without a run pending.
TEST(WorkerPool, EndsWhileIdle) {
    std::atomic<int> calls = 0;
    {
        WorkerPool pool;
        const auto job = [&](int) { ++calls; };
        pool.run(4, job);
        pool.run(1, job);
    }
    EXPECT_EQ(calls, 5);
}

} // namespace
} // namespace casteljau
