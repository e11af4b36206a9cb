// Steady state allocates nothing: a second frame of the same scene reuses
// every buffer of the first (the speed issue's "no allocation per path or
// edge"). Global operator new is replaced in this file to count; the count is
// read only around the frames measured here.
#include "casteljau/render/bands.h"
#include "casteljau/render/worker_pool.h"
#include "casteljau/svg/reader.h"

#include <atomic>
#include <cstdlib>
#include <gtest/gtest.h>
#include <new>

namespace {
std::atomic<long> g_allocations{0};
} // namespace

// GCC flags free() in a replaced operator delete as a mismatch with new: in a
// replacement pair over malloc and free it is the intended match.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
    ++g_allocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace casteljau {
namespace {

template <class Canvas>
long allocations_of_second_frame(const char* file) {
    const SvgResult doc = read_svg_file(std::string(CASTELJAU_EXAMPLES "/svg/") + file);
    EXPECT_TRUE(doc.scene) << doc.error;
    if (!doc.scene) return -1;
    // Bands on one thread: the renderers, the band views and the stats are
    // all kept. On more threads the pool's threads are kept too (below), but
    // which thread draws which band changes from frame to frame, and a
    // thread's renderer grows its buffers the first time it draws a band
    // heavier than any before: steady, but not from the second frame.
    BandRenderer r;
    Canvas canvas(int(doc.scene->width), int(doc.scene->height));
    r.render(*doc.scene, Affine::identity(), canvas, {}, {}, 1);
    const long before = g_allocations;
    r.render(*doc.scene, Affine::identity(), canvas, {}, {}, 1);
    return g_allocations - before;
}

TEST(SteadyState, ASecondFrameAllocatesNothing) {
    for (const char* file : {"dense.svg", "curves.svg", "holes.svg", "stars.svg", "strokes.svg",
                             "transforms.svg", "gradients.svg", "opacity.svg"}) {
        EXPECT_EQ(allocations_of_second_frame<Canvas>(file), 0) << file << ", float";
        EXPECT_EQ(allocations_of_second_frame<Canvas8>(file), 0) << file << ", 8-bit";
    }
}

// The pool's threads wait between runs: a run after the first, on no more
// threads, starts none and allocates nothing.
TEST(SteadyState, AWorkerPoolRunAllocatesNothing) {
    WorkerPool pool;
    std::atomic<int> calls = 0;
    const auto job = [&](int) { ++calls; };
    pool.run(3, job);
    const long before = g_allocations;
    for (int n : {3, 1, 2, 3}) pool.run(n, job);
    EXPECT_EQ(g_allocations - before, 0);
    EXPECT_EQ(calls, 12);
}

} // namespace
} // namespace casteljau
