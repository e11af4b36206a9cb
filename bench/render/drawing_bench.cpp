// The cost of an edit in a drawing application: a large drawing (20,000
// random filled blobs on 1024 x 1024, seeded) rendered whole, against moving
// one small shape and redrawing only the damage (Drawing::replace +
// render_region). The ratio full / edit is the counter to read: the edit's
// cost should follow the dirty area and the shapes crossing it, not the
// drawing's size. Same run, same machine. The redraw of squares of growing
// side shows how the cost follows the area.
#include "casteljau/render/drawing.h"
#include "corpus.h"

#include <benchmark/benchmark.h>

namespace casteljau {
namespace {

constexpr int kSize = 1024;

Drawing& big_drawing() {
    static Drawing d = [] {
        testing::Rng rng(2024);
        Drawing drawing(kSize, kSize);
        for (int i = 0; i < 20000; ++i) {
            const Vec2 at{rng.uniform(0, kSize), rng.uniform(0, kSize)};
            const Rgba c{float(rng.uniform(0, 1)), float(rng.uniform(0, 1)),
                         float(rng.uniform(0, 1)), 0.8f};
            drawing.fill(testing::random_blob(rng, rng.uniform(4, 40), 4), Paint::solid(c),
                         Affine::translate(at));
        }
        return drawing;
    }();
    return d;
}

void BM_DrawingFullRender(benchmark::State& state) {
    Drawing& d = big_drawing();
    Canvas canvas(kSize, kSize);
    for (auto _ : state) {
        d.render(canvas, {1, 1, 1, 1});
        benchmark::DoNotOptimize(canvas.row(0));
    }
}
BENCHMARK(BM_DrawingFullRender)->Unit(benchmark::kMillisecond);

// Moves shape 10000 (a blob of up to 40 px) back and forth by 3 px and
// redraws the union of its old and new boxes.
void BM_DrawingEditAndRedraw(benchmark::State& state) {
    Drawing& d = big_drawing();
    Canvas canvas(kSize, kSize);
    d.render(canvas, {1, 1, 1, 1});
    const Drawing::ShapeId id = 10000;
    Shape s = d.shape(id);
    double dirty_px = 0;
    int step = 0;
    for (auto _ : state) {
        s.transform = Affine::translate({(step++ % 2) ? 3.0 : -3.0, 0}) * s.transform;
        const PixelRect dirty = d.replace(id, s);
        d.render_region(canvas, dirty, {1, 1, 1, 1});
        dirty_px = double(dirty.width()) * dirty.height();
        benchmark::DoNotOptimize(canvas.row(0));
    }
    state.counters["dirty_px"] = dirty_px;
}
BENCHMARK(BM_DrawingEditAndRedraw)->Unit(benchmark::kMicrosecond);

// Redraws a square of side N at the centre: the cost should grow with N^2
// (and the shapes crossing it), reaching the full render's at N = 1024.
void BM_DrawingRedrawSquare(benchmark::State& state) {
    Drawing& d = big_drawing();
    Canvas canvas(kSize, kSize);
    const int n = int(state.range(0)), at = (kSize - n) / 2;
    for (auto _ : state) {
        d.render_region(canvas, {at, at, at + n, at + n}, {1, 1, 1, 1});
        benchmark::DoNotOptimize(canvas.row(at));
    }
    state.counters["dirty_px"] = double(n) * n;
}
BENCHMARK(BM_DrawingRedrawSquare)
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Arg(1024)
    ->Unit(benchmark::kMicrosecond);

} // namespace
} // namespace casteljau

BENCHMARK_MAIN();
