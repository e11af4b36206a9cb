#include "casteljau/render/memory_gate.h"

#include <atomic>
#include <mutex>

namespace casteljau::memory_gate {

namespace {
std::mutex gate;
std::atomic<std::size_t> reserved{0}, shared{kSharedBytes};
thread_local int levels = 0;
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
