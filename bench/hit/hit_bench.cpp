// Hit-testing costs per query, on the seeded random curves of tests/support:
// nearest point on a cubic (roots of a quintic), point in the fill of a
// closed 8-segment blob, cubic-rectangle intersection, and the distance to a
// 6 px stroke of the blob (its outline built at 1e-3 px, as Drawing::shape_at
// asks). An interactive application does a few per mouse move; these say how
// many fit in a frame.
#include "casteljau/hit/nearest.h"
#include "casteljau/hit/rect_hit.h"
#include "casteljau/hit/stroke_hit.h"
#include "casteljau/hit/winding.h"
#include "corpus.h"

#include <benchmark/benchmark.h>
#include <tuple>
#include <utility>
#include <vector>

namespace casteljau {
namespace {

// Runs `query` over 256 seeded inputs made by `make`, round robin.
template <class Make, class Query>
void over_inputs(benchmark::State& state, unsigned seed, Make make, Query query) {
    testing::Rng rng(seed);
    std::vector<decltype(make(rng))> inputs;
    for (int i = 0; i < 256; ++i) inputs.push_back(make(rng));
    std::size_t i = 0;
    for (auto _ : state) {
        const auto& in = inputs[i++ % inputs.size()];
        benchmark::DoNotOptimize(std::apply(query, in));
    }
}

void BM_NearestPointCubic(benchmark::State& state) {
    over_inputs(
        state, 1,
        [](testing::Rng& rng) {
            return std::pair{Segment{testing::random_cubic(rng, 500)}, rng.point(500)};
        },
        [](const Segment& s, Point q) { return nearest_point(s, q); });
}
BENCHMARK(BM_NearestPointCubic);

void BM_FillContainsBlob(benchmark::State& state) {
    over_inputs(
        state, 2,
        [](testing::Rng& rng) {
            return std::pair{testing::random_blob(rng, 500, 8), rng.point(500)};
        },
        [](const Path& p, Point q) { return fill_contains(p, q); });
}
BENCHMARK(BM_FillContainsBlob);

void BM_CubicIntersectsRect(benchmark::State& state) {
    over_inputs(
        state, 3,
        [](testing::Rng& rng) {
            const Segment s = testing::random_cubic(rng, 500);
            const Point a = rng.point(500);
            return std::pair{
                s, Rect::from_points(a, a + Vec2{rng.uniform(0, 100), rng.uniform(0, 100)})};
        },
        [](const Segment& s, const Rect& r) { return segment_intersects_rect(s, r); });
}
BENCHMARK(BM_CubicIntersectsRect);

void BM_StrokeDistanceBlob(benchmark::State& state) {
    StrokeGeometry style;
    style.width = 6;
    over_inputs(
        state, 4,
        [](testing::Rng& rng) {
            return std::pair{testing::random_blob(rng, 500, 8), rng.point(500)};
        },
        [&](const Path& p, Point q) { return stroke_distance(p, style, q); });
}
BENCHMARK(BM_StrokeDistanceBlob);

} // namespace
} // namespace casteljau

BENCHMARK_MAIN();
