// Steady state allocates nothing: a second frame of the same scene reuses
// every buffer of the first (the speed issue's "no allocation per path or
// edge"); and hostile input allocates within its limits. Global operator new
// is replaced in this file to count allocations and keep the largest; both
// are read only around the calls measured here.
#include "casteljau/render/bands.h"
#include "casteljau/render/memory_gate.h"
#include "casteljau/render/worker_pool.h"
#include "casteljau/stroke/stroker.h"
#include "casteljau/svg/reader.h"

#include <atomic>
#include <cstdlib>
#include <gtest/gtest.h>
#include <malloc.h>
#include <new>

namespace {
std::atomic<long> g_allocations{0};
// Bytes held through operator new (as malloc sized the blocks), and the most
// held at once since the test that reads it reset it.
std::atomic<std::size_t> g_held{0}, g_peak_held{0};
} // namespace

// GCC flags free() in a replaced operator delete as a mismatch with new: in a
// replacement pair over malloc and free it is the intended match.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
    ++g_allocations;
    void* p = std::malloc(n ? n : 1);
    if (!p) throw std::bad_alloc();
    const std::size_t held = g_held += malloc_usable_size(p);
    for (std::size_t m = g_peak_held; held > m && !g_peak_held.compare_exchange_weak(m, held);) {
    }
    return p;
}
void operator delete(void* p) noexcept {
    g_held -= malloc_usable_size(p);
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
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

// The pattern tile of tests/fuzz/regressions/svg_render/pattern-tile-7.9e34-px-long.svg
// strokes a circle 1e61 px tall at the device's 0.25 px, which the outline's
// point limit (2^23 a call) drops; but the limit was checked only after each
// segment, whose samples could grow past it first (with libFuzzer's
// bookkeeping, over its 1 GiB). The samples now stop where they could not
// fit. Here, a circle of radius 3 at a tolerance of 2.5e-61: 2^21 vertices
// a quarter.
TEST(Memory, AStrokePastThePointLimitStopsSamplingWhereItCannotFit) {
    Path circle;
    circle.move_to({3, 0});
    const double w = std::sqrt(0.5);
    circle.conic_to({3, 3}, {0, 3}, w);
    circle.conic_to({-3, 3}, {-3, 0}, w);
    circle.conic_to({-3, -3}, {0, -3}, w);
    circle.conic_to({3, -3}, {3, 0}, w);
    circle.close();
    StrokeGeometry thin;
    thin.width = 1;
    Stroker stroker;
    g_peak_held = g_held.load();
    const std::size_t before = g_held;
    const auto polys = stroker.outline(circle, thin, 2.5e-61, Rect{-4, -4, 4, 4});
    EXPECT_TRUE(polys.empty()) << polys.size() << " polygons";
    // 386 MB measured (721 MB before): two segments' samples at 40 bytes,
    // the last one's cut at 2^22, and a quarter's 2^21 vertices.
    EXPECT_LE(g_peak_held - before, std::size_t(1) << 29) << g_peak_held - before << " bytes";
}

// The memory budget (render/memory_gate.h) at `bytes` for a test's scope:
// small, so that small scenes show what large ones do at the default.
class Budget {
  public:
    explicit Budget(std::size_t bytes) { memory_gate::set_budget(bytes); }
    ~Budget() { memory_gate::set_budget(was_); }
    Budget(const Budget&) = delete;
    Budget& operator=(const Budget&) = delete;

  private:
    std::size_t was_ = memory_gate::budget();
};

// Bytes held at most while `scene` renders on `threads` threads.
std::size_t peak_held(const Scene& scene, int threads) {
    BandRenderer r;
    Canvas8 canvas(int(scene.width), int(scene.height));
    g_peak_held = g_held.load();
    const std::size_t before = g_held;
    r.render(scene, Affine::identity(), canvas, {}, {}, threads);
    return g_peak_held - before;
}

// Round U-turns on a stroke 1e6 px wide (as tests/bad_input's
// round_joins_1e6_px_wide.svg): 8,190 outline points a turn in every strip
// of rows. Each thread built its own strips' outlines at once, so the
// memory grew with the threads (a 1024 px file of 8,000 turns: 1.5 GB
// resident on eight, 210 MB on one). Past the budget, one thread at a time
// holds more: four hold what one does, and the budget.
TEST(Memory, HostileStrokesHoldAboutAsMuchOnFourThreadsAsOnOne) {
    std::string d = "M30 30";
    for (int i = 0; i <= 200; ++i) d += i % 2 ? " L30 30" : " L34 30";
    const SvgResult doc = parse_svg(
        "<svg xmlns='http://www.w3.org/2000/svg' width='256' height='512'><path d='" + d +
            "' fill='none' stroke='black' stroke-width='1e6' stroke-linejoin='round'/></svg>",
        "round-joins.svg"); // four strips, four bands
    ASSERT_TRUE(doc.scene) << doc.error;
    const Budget budget(std::size_t(4) << 20);
    const std::size_t one = peak_held(*doc.scene, 1), four = peak_held(*doc.scene, 4);
    // Measured: 31.1 MB on one, 33.3 MB on four (115.8 MB with no budget).
    EXPECT_LE(four, one + (std::size_t(12) << 20)) << "1 thread: " << one << " bytes, 4: " << four;
}

// Sixteen offsets of the source merged: every result held until the merge,
// 23 images of a band's window. Each thread ran its own bands' chains at
// once (sixteen offsets on a 4096 x 1024 file: 1.0 GB resident on one
// thread, 2.6 GB on four); past the budget, one chain at a time runs.
TEST(Memory, HeavyFiltersHoldAboutAsMuchOnFourThreadsAsOnOne) {
    std::string filter = "<filter id='f' x='0' y='0' width='1' height='1'>", merge = "<feMerge>";
    for (int i = 0; i < 16; ++i) {
        const std::string n = std::to_string(i);
        filter += "<feOffset in='SourceGraphic' dx='" + n + "' result='o" + n + "'/>";
        merge += "<feMergeNode in='o" + n + "'/>";
    }
    const SvgResult doc = parse_svg(
        "<svg xmlns='http://www.w3.org/2000/svg' width='512' height='512'>" + filter + merge +
            "</feMerge></filter><rect width='512' height='512' fill='#2a6fb0' "
            "filter='url(#f)'/></svg>",
        "offsets.svg"); // four bands
    ASSERT_TRUE(doc.scene) << doc.error;
    const Budget budget(std::size_t(4) << 20);
    const std::size_t one = peak_held(*doc.scene, 1), four = peak_held(*doc.scene, 4);
    // Measured: 28.2 MB on one, 18.1 MB on four (70.5 MB with no budget).
    EXPECT_LE(four, one + (std::size_t(12) << 20)) << "1 thread: " << one << " bytes, 4: " << four;
}

} // namespace
} // namespace casteljau
