#include "casteljau/render/memory_gate.h"

#include <mutex>

namespace casteljau::memory_gate {

namespace {
std::mutex gate;
thread_local int levels = 0;
} // namespace

void enter() {
    if (levels++ == 0) gate.lock();
}

void leave() {
    if (--levels == 0) gate.unlock();
}

int depth() { return levels; }

} // namespace casteljau::memory_gate
