// Filter speed, measured against baselines in the same run (no Cairo):
// a blur of standard deviation 10 on a 1024 x 1024 layer against a naive
// separable convolution with the same Gaussian (61 taps a pass) and against
// the memory floor (one copy of the layer's 16 MiB); and a drop shadow on
// 2,000 blobs at 1024 px and on the dense example (examples/svg/dense.svg,
// a stroke-heavy drawing standing in for the Ghostscript tiger, which this
// project does not bundle) at 1024 px, each against the same scene
// unfiltered, on 1 and 2 band threads.
#include "../render/bench_scenes.h"
#include "casteljau/filter/blur.h"
#include "casteljau/render/bands.h"
#include "casteljau/svg/reader.h"

#include <benchmark/benchmark.h>
#include <cmath>
#include <cstring>
#include <random>

namespace casteljau {
namespace {

constexpr int kSide = 1024;

FilterImage random_layer() {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0, 1);
    FilterImage img;
    img.reset({0, 0, kSide, kSide}, false);
    for (Premul& p : img.px) {
        p.a = u(rng);
        p.r = p.g = p.b = p.a * 0.5f;
    }
    return img;
}

void BM_Blur_Sigma10(benchmark::State& state) {
    const FilterImage in = random_layer();
    FilterImage out = in;
    for (auto _ : state) {
        gaussian_blur(in, out, {0, 0, kSide, kSide}, 10, 10, EdgeMode::None);
        benchmark::DoNotOptimize(out.px.data());
    }
    state.SetItemsProcessed(state.iterations() * kSide * kSide);
}
BENCHMARK(BM_Blur_Sigma10)->Unit(benchmark::kMillisecond);

// The textbook way: each pass a direct sum over the kernel's 61 taps.
void BM_NaiveSeparableConvolution_Sigma10(benchmark::State& state) {
    const FilterImage in = random_layer();
    FilterImage tmp = in, out = in;
    constexpr int r = 30;
    float k[2 * r + 1];
    float sum = 0;
    for (int i = -r; i <= r; ++i) sum += k[i + r] = std::exp(-i * i / 200.0f);
    for (float& v : k) v /= sum;
    for (auto _ : state) {
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x) {
                Premul s{};
                for (int i = -r; i <= r; ++i) {
                    const Premul p = in.get(x + i, y);
                    s.r += k[i + r] * p.r, s.g += k[i + r] * p.g, s.b += k[i + r] * p.b,
                        s.a += k[i + r] * p.a;
                }
                tmp.at(x, y) = s;
            }
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x) {
                Premul s{};
                for (int i = -r; i <= r; ++i) {
                    const Premul p = tmp.get(x, y + i);
                    s.r += k[i + r] * p.r, s.g += k[i + r] * p.g, s.b += k[i + r] * p.b,
                        s.a += k[i + r] * p.a;
                }
                out.at(x, y) = s;
            }
        benchmark::DoNotOptimize(out.px.data());
    }
    state.SetItemsProcessed(state.iterations() * kSide * kSide);
}
BENCHMARK(BM_NaiveSeparableConvolution_Sigma10)->Unit(benchmark::kMillisecond);

// The floor: reading and writing the layer once.
void BM_CopyLayer(benchmark::State& state) {
    const FilterImage in = random_layer();
    FilterImage out = in;
    for (auto _ : state) {
        std::memcpy(out.px.data(), in.px.data(), in.px.size() * sizeof(Premul));
        benchmark::DoNotOptimize(out.px.data());
    }
    state.SetBytesProcessed(state.iterations() * std::int64_t(in.px.size() * sizeof(Premul)));
}
BENCHMARK(BM_CopyLayer)->Unit(benchmark::kMillisecond);

// `s` with its content in a group under a drop shadow.
Scene shadowed(Scene s) {
    Group g;
    g.children = std::move(s.root.children);
    auto f = std::make_shared<Filter>();
    f->graph.region = {-50, -50, s.width + 50, s.height + 50};
    f->graph.primitives.push_back({DropShadow{4, 4, 6, 8, {0, 0, 0, 0.6f}},
                                   {filter_input::kSourceGraphic},
                                   f->graph.region,
                                   true});
    g.filters.push_back(std::move(f));
    s.root.children.clear();
    s.root.children.push_back(Node{std::move(g)});
    return s;
}

// Frames of `scene` scaled to 1024 px, with a drop shadow (range 0) or
// without, on range(1) threads.
void frames(benchmark::State& state, Scene scene) {
    if (state.range(0) != 0) scene = shadowed(std::move(scene));
    const int threads = int(state.range(1));
    const double k = kSide / std::max(scene.width, scene.height);
    Canvas canvas(int(scene.width * k), int(scene.height * k));
    BandRenderer r;
    for (auto _ : state) {
        r.render(scene, Affine::scale(k), canvas, RenderOptions{}, Premul{}, threads);
        benchmark::DoNotOptimize(canvas.row(0));
    }
    state.SetLabel(std::string(state.range(0) ? "drop shadow" : "plain") + ", " +
                   std::to_string(threads) + " thread(s)");
}

// Plain and shadowed, on 1 and 2 threads.
void frame_cases(benchmark::internal::Benchmark* b) {
    for (int threads : {1, 2}) b->Args({0, threads})->Args({1, threads});
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}

void BM_Blobs2k(benchmark::State& state) { frames(state, bench::random_blobs(7, 2000)); }
BENCHMARK(BM_Blobs2k)->Apply(frame_cases);

void BM_Dense(benchmark::State& state) {
    const SvgResult doc = read_svg_file(CASTELJAU_EXAMPLES "/svg/dense.svg");
    if (!doc.scene) return state.SkipWithError(doc.error.c_str());
    frames(state, *doc.scene);
}
BENCHMARK(BM_Dense)->Apply(frame_cases);

} // namespace
} // namespace casteljau

BENCHMARK_MAIN();
