// Hit-testing costs per query, on the seeded random curves of tests/support:
// nearest point on a cubic (roots of a degree-8 polynomial), point in the
// fill of a closed 8-segment blob, and cubic-rectangle intersection. An
// interactive application does a few per mouse move; these say how many fit
// in a frame.
#include "casteljau/hit/nearest.h"
#include "casteljau/hit/rect_hit.h"
#include "casteljau/hit/winding.h"
#include "corpus.h"

#include <benchmark/benchmark.h>

namespace casteljau {
namespace {

void BM_NearestPointCubic(benchmark::State& state) {
    testing::Rng rng(1);
    std::vector<CubicBez> curves;
    std::vector<Point> queries;
    for (int i = 0; i < 256; ++i) {
        curves.push_back(testing::random_cubic(rng, 500));
        queries.push_back(rng.point(500));
    }
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(nearest_point(Segment{curves[i % 256]}, queries[i % 256]));
        ++i;
    }
}
BENCHMARK(BM_NearestPointCubic);

void BM_FillContainsBlob(benchmark::State& state) {
    testing::Rng rng(2);
    std::vector<Path> blobs;
    std::vector<Point> queries;
    for (int i = 0; i < 256; ++i) {
        blobs.push_back(testing::random_blob(rng, 500, 8));
        queries.push_back(rng.point(500));
    }
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(fill_contains(blobs[i % 256], queries[i % 256]));
        ++i;
    }
}
BENCHMARK(BM_FillContainsBlob);

void BM_CubicIntersectsRect(benchmark::State& state) {
    testing::Rng rng(3);
    std::vector<CubicBez> curves;
    std::vector<Rect> rects;
    for (int i = 0; i < 256; ++i) {
        curves.push_back(testing::random_cubic(rng, 500));
        const Point a = rng.point(500);
        rects.push_back(Rect::from_points(a, a + Vec2{rng.uniform(0, 100), rng.uniform(0, 100)}));
    }
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(segment_intersects_rect(Segment{curves[i % 256]}, rects[i % 256]));
        ++i;
    }
}
BENCHMARK(BM_CubicIntersectsRect);

} // namespace
} // namespace casteljau

BENCHMARK_MAIN();
