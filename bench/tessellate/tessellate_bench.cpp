// Adaptive vs uniform tessellation at equal measured error, per patch kind
// and on multi-patch models, on a 800 x 600 view at --tolerance 0.25 px.
//
// For each model: `adaptive` tessellates under the screen-space bound and
// reports its triangles and measured max error; `uniform` uses the fewest
// steps per patch side whose measured error is at most the adaptive mesh's
// (found once, before timing). Compare `triangles` and the times of the two
// rows of one model, within one run.
#include "casteljau/io/patch_read.h"
#include "casteljau/render3d/camera.h"
#include "casteljau/tessellate/adaptive.h"
#include "casteljau/tessellate/error.h"
#include "casteljau/tessellate/uniform.h"
#include "patch_models.h"

#include <benchmark/benchmark.h>
#include <cmath>
#include <memory>
#include <optional>

namespace casteljau {
namespace {

constexpr double kTolerance = 0.25;
constexpr int kWidth = 800, kHeight = 600;

PatchModel single(AnyPatch p) { return PatchModel{{std::move(p)}}; }

// A saddle: the bilinear patch's only way to be curved is its twist.
PatchModel bilinear_model() {
    BilinearPatch p;
    p.c[0] = {PatchPoint{{0, 0, 0}, {0, 0}}, PatchPoint{{100, 0, 60}, {1, 0}}};
    p.c[1] = {PatchPoint{{0, 100, 60}, {0, 1}}, PatchPoint{{100, 100, 0}, {1, 1}}};
    return single(p);
}

PatchModel quad_model() { return single(test::arch_model().patches[1]); }

// A bicubic patch that is nearly flat except one sharply raised corner.
PatchModel cubic_model() {
    CubicPatch p;
    for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k)
            p.c[r][k] = {{100.0 * k, 100.0 * r, (r == 3 && k == 3) ? 250.0 : 0.0},
                         {k / 3.0, r / 3.0}};
    return single(p);
}

PatchModel file_model(const char* name) {
    return *read_patch_file(std::string(CASTELJAU_EXAMPLES) + "/patch/" + name).model;
}

struct Setup {
    PatchModel model;
    ScreenProjection view;
    int steps = 0;             // uniform steps at the adaptive mesh's error
    double adaptive_error = 0; // px
};

Setup prepare(PatchModel model) {
    Setup s{std::move(model), {}, 0, 0};
    s.view = make_projection(orbit_view(s.model.control_bounds(), 35, 25, kWidth, kHeight), kWidth,
                             kHeight);
    Mesh mesh;
    tessellate_adaptive(s.model, s.view, kTolerance, mesh);
    s.adaptive_error = measure_max_error_px(s.model, mesh, s.view);
    s.steps = fewest_uniform_steps(s.model, s.view, s.adaptive_error, 1024, mesh);
    return s;
}

void run(benchmark::State& state, const Setup& s, bool adaptive) {
    Mesh mesh;
    for (auto _ : state) {
        if (adaptive)
            tessellate_adaptive(s.model, s.view, kTolerance, mesh);
        else
            tessellate_uniform(s.model, s.steps, s.steps, mesh);
        benchmark::DoNotOptimize(mesh.triangles.data());
    }
    state.counters["patches"] = double(s.model.patches.size());
    state.counters["triangles"] = double(mesh.triangles.size());
    state.counters["max_err_px"] = measure_max_error_px(s.model, mesh, s.view);
    state.counters["steps"] = adaptive ? 0 : s.steps;
}

void register_model(const char* name, PatchModel (*make)()) {
    // Built lazily and once, shared by the two rows.
    auto setup = std::make_shared<std::optional<Setup>>();
    const auto get = [setup, make]() -> const Setup& {
        if (!*setup) *setup = prepare(make());
        return **setup;
    };
    benchmark::RegisterBenchmark((std::string("tessellate/") + name + "/adaptive").c_str(),
                                 [get](benchmark::State& st) { run(st, get(), true); })
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("tessellate/") + name + "/uniform").c_str(),
                                 [get](benchmark::State& st) { run(st, get(), false); })
        ->Unit(benchmark::kMicrosecond);
}

} // namespace
} // namespace casteljau

int main(int argc, char** argv) {
    using namespace casteljau;
    register_model("bilinear", bilinear_model);
    register_model("biquadratic", quad_model);
    register_model("bicubic", cubic_model);
    register_model("bspline_bump", test::bump_model);
    register_model("sphere_8_cubic", test::sphere_model);
    register_model("pipe_map_16_quad", [] { return file_model("pipe.map"); });
    register_model("terrain_json_24_bspline", [] { return file_model("terrain.json"); });
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
}
