// `casteljau render IN.svg... -o OUT [--width W | --height H | --scale S] [--tolerance PX]
//   [--flatten adaptive|uniform] [--segments N] [--antialias on|off] [--background COLOR]
//   [--threads N] [--pixels float|u8] [--repeat N] [--stats FILE|-]`
//
// One input renders to OUT (format from its extension); several inputs, or an
// OUT ending in '/', render into that folder as NAME.png. --stats writes one
// JSON object per input (one per line), with the stage times as medians over
// --repeat renders of the already parsed scene.
#include "casteljau/io/atomic_file.h"
#include "casteljau/io/canvas_write.h"
#include "casteljau/render/bands.h"
#include "casteljau/render/output_size.h"
#include "casteljau/svg/color.h"
#include "casteljau/svg/reader.h"
#include "commands.h"
#include "common.h"
#include "json.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <thread>
#include <unistd.h>

namespace casteljau::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kMaxRepeat = 100000;

// The output limits are the library's (render/output_size.h); common.h's
// copies bound the options' ranges and must agree.
static_assert(kMaxSide == kMaxOutputSide && kMaxPixels == kMaxOutputPixels);

struct RenderArgs {
    std::vector<std::string> inputs;
    std::string output;
    double width = 0, height = 0, scale = 0;
    FlattenOptions flatten;
    SvgOptions svg;
    bool antialias = true;
    bool linear_light = false;
    std::string background;
    int threads = 0;
    bool u8 = false; // --pixels u8: draw onto a Canvas8
    int repeat = 1;
    std::string stats;
};

int threads(const RenderArgs& a) {
    return a.threads > 0 ? a.threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Outcome {
    int status = kExitOk;
    std::string stats_json;
};

template <class Target>
Outcome render_one(const RenderArgs& a, const std::string& input, const std::string& output,
                   Premul background, BandRenderer& renderer, Target& canvas) {
    Outcome out;
    const auto t0 = Clock::now();
    const std::optional<Scene> loaded = load_svg(input, a.svg, out.status);
    if (!loaded) return out;
    const Scene& scene = *loaded;
    const double parse_ms = ms(Clock::now() - t0);
    const OutputSize size = output_size(scene.width, scene.height, {a.width, a.height, a.scale});
    if (!size.error.empty()) {
        std::fprintf(stderr, "error: %s: %s\n", input.c_str(), size.error.c_str());
        out.status = kExitBadInput;
        return out;
    }
    const double s = size.scale;
    const int w = size.width, h = size.height;
    const RenderOptions options{.flatten = a.flatten,
                                .antialias = a.antialias,
                                .linear_light_gradients = a.linear_light,
                                .time_stages = !a.stats.empty()};
    std::vector<double> flatten_ms, raster_ms, frame_ms;
    RenderStats stats;
    for (int i = 0; i < a.repeat; ++i) {
        const auto f0 = Clock::now();
        canvas.resize(w, h); // the renderer clears each band to the background
        stats = renderer.render(scene, Affine::scale(s), canvas, options, background, threads(a));
        frame_ms.push_back(ms(Clock::now() - f0));
        flatten_ms.push_back(stats.flatten_ms);
        raster_ms.push_back(stats.raster_ms);
    }
    const auto e0 = Clock::now();
    const std::string err = write_canvas_atomic(output, canvas);
    const double encode_ms = ms(Clock::now() - e0);
    if (!err.empty()) {
        std::fprintf(stderr, "error: %s\n", err.c_str());
        out.status = kExitFailure;
        return out;
    }
    const double total_ms = ms(Clock::now() - t0);
    if (a.stats.empty()) return out;
    // Segment counts and the exact flattening error, from a separate, untimed
    // single-band pass (bands repeat the flattening of shapes they share).
    Canvas scratch{w, h};
    Renderer measure;
    const RenderStats m = measure.render(
        scene, Affine::scale(s), scratch,
        {.flatten = options.flatten, .antialias = a.antialias, .measure_error = true});
    stats.flatten = m.flatten;
    out.stats_json = "{\"input\": " + json_string(input) + ", \"output\": " + json_string(output) +
                     ", \"segments_in\": " + std::to_string(stats.flatten.curves_in) +
                     ", \"segments_out\": " + std::to_string(stats.flatten.segments_out) +
                     ", \"max_error_px\": " + json_number(m.flatten.max_error) +
                     ", \"parse_ms\": " + json_number(parse_ms) +
                     ", \"flatten_ms\": " + json_number(median(flatten_ms)) +
                     ", \"raster_ms\": " + json_number(median(raster_ms)) +
                     ", \"encode_ms\": " + json_number(encode_ms) +
                     ", \"frame_ms\": " + json_number(median(frame_ms)) +
                     ", \"total_ms\": " + json_number(total_ms) +
                     ", \"width\": " + std::to_string(w) + ", \"height\": " + std::to_string(h) +
                     ", \"threads\": " + std::to_string(threads(a)) +
                     ", \"pixels\": " + (a.u8 ? "\"u8\"" : "\"float\"") +
                     ", \"repeat\": " + std::to_string(a.repeat) + "}";
    return out;
}

int run_render(const RenderArgs& a) {
    if (!check_tolerance("render", a.flatten.tolerance)) return kExitBadInput;
    Premul background{};
    if (!a.background.empty()) {
        const auto c = parse_color(a.background);
        if (!c) {
            std::fprintf(stderr, "casteljau render: --background '%s' is not a color\n",
                         a.background.c_str());
            return kExitBadInput;
        }
        background = premultiply(*c);
    }
    const bool to_folder = a.inputs.size() > 1 || (!a.output.empty() && a.output.back() == '/');
    if (to_folder) {
        std::error_code ec;
        fs::create_directories(a.output, ec);
        if (ec) {
            std::fprintf(stderr, "casteljau render: -o %s: cannot create the folder: %s\n",
                         a.output.c_str(), ec.message().c_str());
            return kExitFailure;
        }
    }
    const bool progress = to_folder && ::isatty(2);
    BandRenderer renderer;
    Canvas canvas;
    Canvas8 canvas8;
    int status = kExitOk;
    std::string stats;
    for (std::size_t i = 0; i < a.inputs.size(); ++i) {
        const std::string& in = a.inputs[i];
        const std::string out =
            to_folder ? (fs::path(a.output) / fs::path(in).stem()).string() + ".png" : a.output;
        if (progress)
            std::fprintf(stderr, "\r[%zu/%zu] %s\033[K", i + 1, a.inputs.size(), in.c_str());
        const Outcome o = a.u8 ? render_one(a, in, out, background, renderer, canvas8)
                               : render_one(a, in, out, background, renderer, canvas);
        status = std::max(status, o.status);
        if (!o.stats_json.empty()) stats += o.stats_json + "\n";
    }
    if (progress) std::fprintf(stderr, "\n");
    if (!a.stats.empty() && !stats.empty()) {
        if (a.stats == "-") {
            std::fputs(stats.c_str(), stdout);
        } else if (const std::string err = write_file_atomic(a.stats, stats); !err.empty()) {
            std::fprintf(stderr, "error: --stats %s\n", err.c_str());
            status = std::max(status, kExitFailure);
        }
    }
    return status;
}

} // namespace

Command add_render_command(CLI::App& app) {
    auto a = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Render SVG files to images");
    cmd->add_option("inputs", a->inputs, "SVG files")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", a->output,
                    "Output image (png, tif, exr, jpg), or a folder for several inputs")
        ->required();
    auto* w = cmd->add_option("--width", a->width, "Output width in px (keeps the aspect ratio)")
                  ->check(CLI::Range(1.0, double(kMaxSide)));
    auto* h = cmd->add_option("--height", a->height, "Output height in px (keeps the aspect ratio)")
                  ->check(CLI::Range(1.0, double(kMaxSide)));
    auto* s = cmd->add_option("--scale", a->scale, "Scale factor from the document size")
                  ->check(CLI::Range(1e-6, 1e6));
    w->excludes(h)->excludes(s);
    h->excludes(s);
    add_flatten_options(cmd, a->flatten);
    add_svg_options(cmd, a->svg);
    const std::map<std::string, bool> onoff{{"on", true}, {"off", false}};
    cmd->add_option("--antialias", a->antialias,
                    "on (exact-area coverage, default) or off (pixel centres)")
        ->transform(CLI::CheckedTransformer(onoff, CLI::ignore_case));
    const std::map<std::string, bool> spaces{{"srgb", false}, {"linear", true}};
    cmd->add_option("--gradient-interpolation", a->linear_light,
                    "srgb (default, as SVG 1.1) or linear (linear light)")
        ->transform(CLI::CheckedTransformer(spaces, CLI::ignore_case));
    cmd->add_option("--background", a->background, "Background color (default transparent)");
    cmd->add_option("--threads", a->threads,
                    "Threads rendering bands of rows (default: all cores); the output is the same")
        ->check(CLI::Range(1, 1024));
    const std::map<std::string, bool> pixels{{"float", false}, {"u8", true}};
    cmd->add_option("--pixels", a->u8,
                    "float (default: exact compositing) or u8 (8 bits a channel, rounded at "
                    "each composite as Cairo does; a quarter of the memory, faster)")
        ->transform(CLI::CheckedTransformer(pixels, CLI::ignore_case));
    cmd->add_option("--repeat", a->repeat,
                    "Render the parsed scene N times; stage times are medians")
        ->check(CLI::Range(1, kMaxRepeat));
    cmd->add_option("--stats", a->stats,
                    "Write timing and error statistics as JSON to FILE, or - for stdout");
    return [a] { return run_render(*a); };
}

} // namespace casteljau::cli
