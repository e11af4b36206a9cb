// Casteljau against Cairo on the same scenes, in one binary and one run.
//
// Each iteration renders the frame with both, one thread each, timed
// separately: Casteljau's BandRenderer at its default 0.25 px tolerance into
// its float canvas (`float`) or its 8-bit one (`u8`, Cairo's pixel size),
// and Cairo (cairo_scene.h) at its default 0.1 px into an ARGB32 image
// surface, both cleared to white first. The reported time is Casteljau's;
// the counters give Cairo's time and the ratio casteljau / cairo (below 1:
// Casteljau is faster). A second run of each scene with Casteljau at 0.1 px
// compares them at equal tolerance.
// diff_255 is the mean difference of the two pictures per channel, in
// 1/255: a check that both drew the same thing at comparable quality.
//
// Usage: cairo_compare_bench [benchmark flags] [SCENE.svg ...]
// The seeded scenes of bench_scenes.h (the and the shaded paints')
// always run; each SVG argument is added,
// scaled so that its longer side is 1024 px (the tiger at 1024 px).
#include "bench_scenes.h"
#include "cairo_scene.h"
#include "casteljau/render/bands.h"
#include "casteljau/svg/reader.h"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <type_traits>

namespace casteljau::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// Mean absolute difference of the two frames' color channels, in 1/255:
// the check that both drew the same picture (premultiplied, over white).
template <class Canvas>
double mean_difference(const Canvas& ours, cairo_surface_t* surface) {
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    double sum = 0;
    for (int y = 0; y < ours.height(); ++y) {
        const auto* px = reinterpret_cast<const std::uint32_t*>(data + std::ptrdiff_t(y) * stride);
        for (int x = 0; x < ours.width(); ++x) {
            const Premul p = to_premul(ours.row(y)[x]);
            const std::uint32_t c = px[x]; // ARGB32: 0xAARRGGBB, premultiplied
            sum += std::fabs(p.r * 255 - float((c >> 16) & 255)) +
                   std::fabs(p.g * 255 - float((c >> 8) & 255)) +
                   std::fabs(p.b * 255 - float(c & 255));
        }
    }
    return sum / (3.0 * ours.width() * ours.height());
}

template <class Canvas>
void compare(benchmark::State& state, const Scene& scene, double scale, double tolerance) {
    const int w = int(std::ceil(scene.width * scale)), h = int(std::ceil(scene.height * scale));
    BandRenderer ours;
    Canvas canvas(w, h);
    RenderOptions options;
    options.flatten.tolerance = tolerance;
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    cairo_t* cr = cairo_create(surface);
    double ours_s = 0, cairo_s = 0;
    for (auto _ : state) {
        auto t = Clock::now();
        ours.render(scene, Affine::scale(scale), canvas, options, {1, 1, 1, 1}, 1);
        const double ours_frame = seconds_since(t);
        benchmark::DoNotOptimize(canvas.row(0));
        t = Clock::now();
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_paint(cr);
        cairo_save(cr);
        cairo_scale(cr, scale, scale);
        draw_with_cairo(cr, scene);
        cairo_restore(cr);
        cairo_surface_flush(surface);
        cairo_s += seconds_since(t);
        ours_s += ours_frame;
        state.SetIterationTime(ours_frame);
    }
    const double n = double(state.iterations());
    state.counters["cairo_ms"] = 1e3 * cairo_s / n;
    state.counters["ratio"] = ours_s / cairo_s;
    state.counters["diff_255"] = mean_difference(canvas, surface);
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
}

template <class Canvas>
void register_scene(const std::string& name, const std::shared_ptr<const Scene>& scene,
                    double scale) {
    const std::string format = std::is_same_v<Canvas, Canvas8> ? "/u8" : "/float";
    for (double tol : {0.25, 0.1}) {
        const std::string label = name + format + (tol == 0.25 ? "/tol:0.25" : "/tol:0.1");
        benchmark::RegisterBenchmark(
            label.c_str(),
            [scene, scale, tol](benchmark::State& s) { compare<Canvas>(s, *scene, scale, tol); })
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
    }
}

void register_scene(const std::string& name, std::shared_ptr<const Scene> scene,
                    double scale = 1.0) {
    register_scene<Canvas>(name, scene, scale);
    register_scene<Canvas8>(name, scene, scale);
}

} // namespace
} // namespace casteljau::bench

int main(int argc, char** argv) {
    using namespace casteljau;
    benchmark::Initialize(&argc, argv);
    for (auto& s : bench::standard_scenes())
        bench::register_scene(s.name, std::make_shared<const Scene>(std::move(s.scene)));
    for (auto& s : bench::paint_scenes())
        bench::register_scene(s.name, std::make_shared<const Scene>(std::move(s.scene)));
    for (int i = 1; i < argc; ++i) {
        SvgResult r = read_svg_file(argv[i]);
        if (!r.scene) {
            std::fprintf(stderr, "%s\n", r.error.c_str());
            return 2;
        }
        const double side = std::max(r.scene->width, r.scene->height);
        bench::register_scene(argv[i], std::make_shared<const Scene>(std::move(*r.scene)),
                              bench::kSceneSize / side);
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
