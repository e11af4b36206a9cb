// The PNG encoder (io/png_write.h): time and size for each filter choice and
// libdeflate level, on pictures rendered 1024 px wide from examples/svg and
// from every SVG given on the command line (the Ghostscript tiger is the
// issue's reference). Counters: `bytes` (the file's size) and `MB_per_s` of
// 8-bit RGBA input. Compare `bytes` with rsvg-convert's PNG of the same
// picture (`rsvg-convert -w 1024 IN.svg -o OUT.png`). Also the step before
// encoding, the float canvas to straight 8-bit RGBA (`/straight_rgba8`).
#include "casteljau/io/png_write.h"
#include "casteljau/paint/straight_rgba.h"
#include "casteljau/render/renderer.h"
#include "casteljau/svg/reader.h"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace casteljau {
namespace {

constexpr int kWidth = 1024; // the output width

struct Picture {
    std::string name;
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
    std::shared_ptr<const Canvas> canvas; ///< what rgba was converted from
};

/// The SVG at `path` rendered kWidth wide as straight 8-bit RGBA, or an
/// empty picture (with a message) when it cannot be read.
Picture render(const std::string& path) {
    SvgResult r = read_svg_file(path);
    if (!r.scene || r.scene->width <= 0 || r.scene->height <= 0) {
        std::fprintf(stderr, "%s: %s\n", path.c_str(), r.error.c_str());
        return {};
    }
    const double s = kWidth / r.scene->width;
    Picture p{std::filesystem::path(path).stem().string(),
              kWidth,
              std::max(1, int(r.scene->height * s + 0.5)),
              {},
              nullptr};
    auto canvas = std::make_shared<Canvas>(p.width, p.height);
    Renderer().render(*r.scene, Affine::scale(s), *canvas, RenderOptions{});
    p.rgba.resize(std::size_t(p.width) * std::size_t(p.height) * 4);
    straight_rgba8(*canvas, p.rgba);
    p.canvas = std::move(canvas);
    return p;
}

// The step before encoding: the float canvas to straight 8-bit RGBA.
void to_bytes(benchmark::State& state, const Picture& p) {
    std::vector<std::uint8_t> out(p.rgba.size());
    for (auto _ : state) {
        straight_rgba8(*p.canvas, out);
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["MB_per_s"] = benchmark::Counter(double(out.size()) * 1e-6,
                                                    benchmark::Counter::kIsIterationInvariantRate);
}

void encode(benchmark::State& state, const Picture& p, PngOptions options) {
    std::size_t bytes = 0;
    for (auto _ : state) {
        const std::vector<std::uint8_t> png = encode_png(p.rgba, p.width, p.height, options);
        bytes = png.size();
        benchmark::DoNotOptimize(png.data());
    }
    state.counters["bytes"] = double(bytes);
    state.counters["MB_per_s"] = benchmark::Counter(double(p.rgba.size()) * 1e-6,
                                                    benchmark::Counter::kIsIterationInvariantRate);
}

void register_picture(const Picture& p) {
    benchmark::RegisterBenchmark((p.name + "/straight_rgba8").c_str(), [p](benchmark::State& s) {
        to_bytes(s, p);
    })->Unit(benchmark::kMillisecond);
    const char* names[] = {"none", "sub", "up", "average", "paeth", "adaptive", "automatic"};
    // none (the choice for most renders) and the two choosers at every level
    // worth having; the other single filters at the default level.
    for (int f = 0; f <= int(PngFilter::automatic); ++f)
        for (int level : {1, 2, 3, 4, 5, 6, 9, 12}) {
            const bool every_level = f == int(PngFilter::none) || f >= int(PngFilter::adaptive);
            if (!every_level && level != PngOptions{}.level) continue;
            const std::string label = p.name + "/" + names[f] + "/level:" + std::to_string(level);
            benchmark::RegisterBenchmark(label.c_str(), [p, f, level](benchmark::State& s) {
                encode(s, p, {level, PngFilter(f)});
            })->Unit(benchmark::kMillisecond);
        }
}

} // namespace
} // namespace casteljau

int main(int argc, char** argv) {
    using namespace casteljau;
    benchmark::Initialize(&argc, argv);
    std::vector<std::string> inputs;
    for (const auto& e : std::filesystem::directory_iterator(CASTELJAU_EXAMPLES "/svg"))
        if (e.path().extension() == ".svg") inputs.push_back(e.path().string());
    std::sort(inputs.begin(), inputs.end());
    for (int i = 1; i < argc; ++i) inputs.emplace_back(argv[i]);
    for (const std::string& path : inputs) {
        const Picture p = render(path);
        if (p.rgba.empty()) return 2;
        register_picture(p);
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
