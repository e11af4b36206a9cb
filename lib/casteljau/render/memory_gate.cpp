#include "casteljau/render/memory_gate.h"

#include <atomic>
#include <mutex>
#include <pthread.h>

namespace casteljau::memory_gate {

namespace {
std::mutex gate;
std::atomic<std::size_t> reserved{0}, shared{kSharedBytes};
thread_local int levels = 0;

// Around fork(): the forking thread takes the gate (unless it is through it
// already), so that no other thread holds it at the fork; parent and child
// then release it.
void before_fork() {
    if (levels == 0) gate.lock();
}
void after_fork() {
    if (levels == 0) gate.unlock();
}
[[maybe_unused]] const int fork_handlers = pthread_atfork(before_fork, after_fork, after_fork);
} // namespace

void set_budget(std::size_t bytes) { shared.store(bytes, std::memory_order_relaxed); }

std::size_t budget() { return shared.load(std::memory_order_relaxed); }

bool reserve(std::size_t bytes) {
    const std::size_t most = budget();
    std::size_t now = reserved.load(std::memory_order_relaxed);
    while (levels == 0 && now <= most && bytes <= most - now)
        if (reserved.compare_exchange_weak(now, now + bytes, std::memory_order_relaxed))
            return true;
    enter();
    return false;
}

void unreserve(std::size_t bytes) { reserved.fetch_sub(bytes, std::memory_order_relaxed); }

void enter() {
    if (levels == 0) gate.lock(); // counted once locked: a throwing lock leaves none
    ++levels;
}

void leave() {
    if (--levels == 0) gate.unlock();
}

int depth() { return levels; }

} // namespace casteljau::memory_gate
