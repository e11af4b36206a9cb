// Frame times of whole renders (flatten + raster + composite; no parse, no
// encode): the bundled dense scene (examples/svg/dense.svg, 3000 shapes at
// 1024 x 768) and a full-canvas rectangle, whose pixels/s are compared with a
// memset of the same buffer (the bandwidth limit) in the same run. Each on
// both canvases: float (Canvas, 16 bytes a pixel) and 8-bit (Canvas8, 4).
// Thread scaling, 1 to 2 threads, on the dense scene and on each scene of
// cairo_compare_bench, next to what the machine gives the same work.
// BM_Frame: one-thread frames of each scene of cairo_compare_bench and of
// each SVG argument, without Cairo's frames in between: the loop for A/B runs
// of two builds (run the two binaries alternately on one core).
//
// Usage: render_bench [benchmark flags] [SCENE.svg ...]
#include "bench_scenes.h"
#include "casteljau/curve/path_data.h"
#include "casteljau/raster/path_edges.h"
#include "casteljau/raster/rasterizer.h"
#include "casteljau/render/bands.h"
#include "casteljau/render/worker_pool.h"
#include "casteljau/svg/reader.h"

#include <algorithm>
#include <atomic>
#include <benchmark/benchmark.h>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace casteljau {
namespace {

Scene load(const std::string& path) {
    SvgResult r = read_svg_file(path);
    if (!r.scene) {
        std::fprintf(stderr, "%s\n", r.error.c_str());
        std::exit(1);
    }
    return std::move(*r.scene);
}

template <class Canvas>
void render_frames(benchmark::State& state, const Scene& scene, bool antialias,
                   double scale = 1.0) {
    BandRenderer renderer;
    Canvas canvas;
    RenderOptions options;
    options.antialias = antialias;
    std::size_t segments = 0;
    // The renderer clears every pixel to the background itself.
    const int w = int(std::ceil(scene.width * scale)), h = int(std::ceil(scene.height * scale));
    canvas.reset(w, h);
    for (auto _ : state) {
        segments = renderer.render(scene, Affine::scale(scale), canvas, options, {}, 1)
                       .flatten.segments_out;
        benchmark::DoNotOptimize(canvas.row(0));
    }
    const double px = double(w) * h;
    state.counters["Mpixels_per_s"] =
        benchmark::Counter(px * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["segments"] = double(segments);
}

template <class Canvas>
void BM_DenseScene(benchmark::State& state) {
    static const Scene scene = load(CASTELJAU_EXAMPLES "/svg/dense.svg");
    render_frames<Canvas>(state, scene, state.range(0) != 0);
}
void antialias_on_and_off(benchmark::internal::Benchmark* b) {
    b->Arg(1)->Arg(0)->ArgName("antialias")->Unit(benchmark::kMillisecond);
}
BENCHMARK_TEMPLATE(BM_DenseScene, Canvas)->Apply(antialias_on_and_off);
BENCHMARK_TEMPLATE(BM_DenseScene, Canvas8)->Apply(antialias_on_and_off);

// The machine's own scaling, as references for the renderer's: the same
// sharing out (6 units taken from a shared counter by 1 or 2 threads of a
// WorkerPool, as BandRenderer's), of work that shares no data, so on an idle
// machine with private cores two threads take half the time; what they
// lose, the machine takes. Two kinds of unit, each lasting about as long as
// one of the dense scene's bands (2-4 ms on the machine of bench/README.md):
// - memory: 80 read-modify-write passes over a private buffer the size of a
//   band's pixels (128 rows of 1024 float RGBA pixels, 2 MiB). More memory-
//   bound than rendering, so a floor to compare with, not a ceiling;
// - compute: a chain of 2^21 integer multiply-adds in registers (a ceiling),
//   the steps of Knuth's MMIX linear congruential generator, each depending
//   on the last so that no compiler can shorten the chain.
enum class Work { Memory, Compute };

void reference_frame(Work kind, int threads, WorkerPool& pool) {
    constexpr int kUnits = 6, kPasses = 80;
    constexpr long kSteps = 1L << 21;
    static std::vector<float> buffers[2] = {std::vector<float>(128 * 1024 * 4, 1.0f),
                                            std::vector<float>(128 * 1024 * 4, 1.0f)};
    std::atomic<int> next{0};
    const auto work = [&](int t) {
        std::vector<float>& b = buffers[t];
        std::uint64_t x = 1;
        for (int u = next++; u < kUnits; u = next++) {
            if (kind == Work::Memory)
                for (int p = 0; p < kPasses; ++p)
                    for (float& v : b) v = v * 0.999f + 0.001f;
            else
                for (long i = 0; i < kSteps; ++i)
                    x = x * 6364136223846793005u + 1442695040888963407u;
        }
        benchmark::DoNotOptimize(b.data());
        benchmark::DoNotOptimize(x);
    };
    pool.run(threads, work);
}

// Two whole frames at once, one per thread of `pool`, each drawn by its own
// one-thread BandRenderer into its own canvas: the work of two one-thread
// frames with nothing shared and no band to wait for.
template <class Canvas>
void independent_frames(const Scene& scene, BandRenderer (&renderers)[2], Canvas (&canvases)[2],
                        WorkerPool& pool) {
    pool.run(
        2, [&](int t) { renderers[t].render(scene, Affine::identity(), canvases[t], {}, {}, 1); });
}

// The scaling ratio measured frame against frame: every iteration renders the
// scene on 1 thread and then on 2, so both see the same machine load (on a
// shared machine the 1-thread time alone moves by 30% between runs), and
// runs three references in the same iterations:
// - independent: the scene as two whole frames at once (independent_frames)
//   against one frame on one thread. Its ratio, 2 x one frame / two at once,
//   is what this machine gives this very workload on two threads when
//   nothing is shared out: the same pixels, memory and instructions per
//   thread, and no band to wait for (at twice the pixel memory, so a split
//   frame can beat it where the canvas crowds the cache). Where the
//   renderer's speedup matches it, sharing the frame out costs nothing
//   beyond what the machine takes from any two threads;
// - memory and compute (reference_frame), each on 1 and on 2 threads: work
//   that shares no data, more memory-bound and less than rendering.
// Counters: one_thread_ms, two_threads_ms, speedup (their ratio), and the
// references' ratios in the same iterations: independent_speedup,
// memory_speedup, compute_speedup.
template <class Canvas>
void thread_scaling(benchmark::State& state, const Scene& scene) {
    BandRenderer renderer, pair[2];
    WorkerPool pool;
    const int w = int(scene.width), h = int(scene.height);
    Canvas canvas(w, h), pair_canvases[2] = {Canvas(w, h), Canvas(w, h)};
    double one = 0, two = 0, independent = 0;
    double ref[2][2] = {}; // [memory, compute][1 thread, 2 threads]
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::duration d) {
        return std::chrono::duration<double, std::milli>(d).count();
    };
    for (auto _ : state) {
        const auto t0 = Clock::now();
        renderer.render(scene, Affine::identity(), canvas, {}, {}, 1);
        const auto t1 = Clock::now();
        renderer.render(scene, Affine::identity(), canvas, {}, {}, 2);
        const auto t2 = Clock::now();
        independent_frames(scene, pair, pair_canvases, pool);
        independent += ms(Clock::now() - t2);
        for (Work kind : {Work::Memory, Work::Compute})
            for (int threads : {1, 2}) {
                const auto r0 = Clock::now();
                reference_frame(kind, threads, pool);
                ref[int(kind)][threads - 1] += ms(Clock::now() - r0);
            }
        one += ms(t1 - t0), two += ms(t2 - t1);
        state.SetIterationTime(std::chrono::duration<double>(t2 - t0).count());
    }
    const double n = double(state.iterations());
    state.counters["one_thread_ms"] = one / n;
    state.counters["two_threads_ms"] = two / n;
    state.counters["speedup"] = one / two;
    state.counters["independent_speedup"] = 2 * one / independent;
    state.counters["memory_speedup"] = ref[0][0] / ref[0][1];
    state.counters["compute_speedup"] = ref[1][0] / ref[1][1];
}

template <class Canvas>
void BM_ThreadScaling(benchmark::State& state) {
    static const Scene scene = load(CASTELJAU_EXAMPLES "/svg/dense.svg");
    thread_scaling<Canvas>(state, scene);
}
BENCHMARK_TEMPLATE(BM_ThreadScaling, Canvas)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_ThreadScaling, Canvas8)->UseManualTime()->Unit(benchmark::kMillisecond);

// The same on each scene of cairo_compare_bench (bench_scenes.h), float
// canvas: BM_ThreadScaling/blobs_2k, ... (built at start-up, in 0.05 s).
const bool kSceneScalingRegistered = [] {
    static const std::vector<bench::NamedScene> scenes = bench::standard_scenes();
    for (const bench::NamedScene& named : scenes) {
        const Scene* scene = &named.scene;
        benchmark::RegisterBenchmark(
            ("BM_ThreadScaling/" + named.name).c_str(),
            [scene](benchmark::State& state) { thread_scaling<Canvas>(state, *scene); })
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
    }
    return true;
}();

template <class Canvas>
void BM_FullCanvasFill(benchmark::State& state) {
    static const Scene scene = [] {
        SvgResult r = parse_svg(
            R"(<svg width="2048" height="2048"><rect width="2048" height="2048" fill="teal"/></svg>)",
            "full.svg");
        return std::move(*r.scene);
    }();
    render_frames<Canvas>(state, scene, true);
}
BENCHMARK_TEMPLATE(BM_FullCanvasFill, Canvas)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_FullCanvasFill, Canvas8)->Unit(benchmark::kMillisecond);

// The reference: a memset of the same 2048 x 2048 buffer (64 MiB of float
// RGBA, 16 MiB of 8-bit), to zero bytes and to a non-zero byte. The fill
// must write non-zero data, and some machines write zeros to memory at a
// multiple of the bandwidth of anything else (on the 2-core AMD EPYC VM of
// bench/README.md, a 64 MiB memset to 0 ran 2.5x faster than to 0x5a, and
// than any store loop we tried: SSE2, AVX2 and AVX-512 streaming stores,
// rep stosq; at 16 MiB, within the last-level cache, the two are equal).
template <class Pixel>
void BM_MemsetSameBuffer(benchmark::State& state) {
    std::vector<Pixel> buf(std::size_t(2048) * 2048);
    const int byte = int(state.range(0));
    for (auto _ : state) {
        std::memset(static_cast<void*>(buf.data()), byte, buf.size() * sizeof(Pixel));
        benchmark::DoNotOptimize(buf.data());
    }
    state.counters["Mpixels_per_s"] =
        benchmark::Counter(2048.0 * 2048 * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}
void zero_and_non_zero_bytes(benchmark::internal::Benchmark* b) {
    b->Arg(0)->Arg(0x5a)->ArgName("byte")->Unit(benchmark::kMillisecond);
}
BENCHMARK_TEMPLATE(BM_MemsetSameBuffer, Premul)->Apply(zero_and_non_zero_bytes);
BENCHMARK_TEMPLATE(BM_MemsetSameBuffer, Premul8)->Apply(zero_and_non_zero_bytes);

// The rasterizer alone (edges -> spans, no canvas) on a 24 px circle placed
// in a 64 px frame and in a 16384 px frame: the cost follows the outline and
// the covered spans, not the frame's area, so the two should match.
void BM_SmallShapeRaster(benchmark::State& state) {
    const int side = int(state.range(0));
    const Path circle = parse_path_data("M 44 32 A 12 12 0 1 1 20 32 A 12 12 0 1 1 44 32 Z").path;
    struct Count final : SpanSink {
        long pixels = 0;
        void span(const Span& s) override { pixels += s.len; }
    } sink;
    EdgeList edges;
    Rasterizer raster;
    for (auto _ : state) {
        edges.reset(side, side);
        add_path_edges(circle, Affine::identity(), {}, edges);
        raster.fill(edges, FillRule::NonZero, true, sink);
    }
    benchmark::DoNotOptimize(sink.pixels);
}
BENCHMARK(BM_SmallShapeRaster)
    ->Arg(64)
    ->Arg(16384)
    ->ArgName("frame")
    ->Unit(benchmark::kMicrosecond);

// One-thread frames of `scene` on one canvas, as the benchmark `label`.
template <class Canvas>
void register_frame(const std::string& label, std::shared_ptr<const Scene> scene, double scale) {
    benchmark::RegisterBenchmark(label.c_str(), [scene, scale](benchmark::State& state) {
        render_frames<Canvas>(state, *scene, true, scale);
    })->Unit(benchmark::kMillisecond);
}

// Frames of one scene on both canvases: BM_Frame/<name>/float, .../u8.
void register_frames(const std::string& name, const std::shared_ptr<const Scene>& scene,
                     double scale) {
    register_frame<Canvas>("BM_Frame/" + name + "/float", scene, scale);
    register_frame<Canvas8>("BM_Frame/" + name + "/u8", scene, scale);
}

} // namespace
} // namespace casteljau

int main(int argc, char** argv) {
    using namespace casteljau;
    benchmark::Initialize(&argc, argv);
    for (bench::NamedScene& s : bench::standard_scenes())
        register_frames(s.name, std::make_shared<const Scene>(std::move(s.scene)), 1.0);
    for (bench::NamedScene& s : bench::paint_scenes())
        register_frames(s.name, std::make_shared<const Scene>(std::move(s.scene)), 1.0);
    // Each SVG argument scaled so that its longer side is 1024 px, as in
    // cairo_compare_bench (the issue's tiger at 1024 px).
    for (int i = 1; i < argc; ++i) {
        Scene scene = load(argv[i]);
        const double scale = bench::kSceneSize / std::max(scene.width, scene.height);
        register_frames(argv[i], std::make_shared<const Scene>(std::move(scene)), scale);
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
