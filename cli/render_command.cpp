// `casteljau render IN.svg... [--from-list FILE|-] -o OUT [--width W | --height H | --scale S]
//   [--tolerance PX] [--flatten adaptive|uniform] [--segments N] [--antialias on|off]
//   [--background COLOR] [--threads N] [--pixels auto|float|u8] [--repeat N] [--stats FILE|-]`
//
// One input renders to OUT (format from its extension); several inputs, a
// list, or an OUT ending in '/' render into that folder as NAME.png, on
// every thread (render_batch.cpp). --stats writes one JSON object per input
// (one per line, in input order), with the stage times as medians over
// --repeat renders of the already parsed scene.
#include "casteljau/io/atomic_file.h"
#include "casteljau/render/output_size.h"
#include "casteljau/svg/color.h"
#include "commands.h"
#include "common.h"
#include "render_batch.h"
#include "render_file.h"
#include "render_inputs.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <unistd.h>
#include <vector>

namespace casteljau::cli {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxRepeat = 100000;

// The output limits are the library's (render/output_size.h); common.h's
// copies bound the options' ranges and must agree.
static_assert(kMaxSide == kMaxOutputSide && kMaxPixels == kMaxOutputPixels);

// The inputs from the arguments, then from the list; nullopt (after a
// message) when the list cannot be read.
std::optional<std::vector<RenderJob>> gather_inputs(const RenderArgs& a) {
    std::vector<RenderJob> jobs;
    for (const std::string& in : a.inputs) jobs.push_back(checked_job(in, ""));
    std::string error;
    if (!a.from_list.empty() && !read_input_list(a.from_list, jobs, error)) {
        std::fprintf(stderr, "casteljau render: %s\n", error.c_str());
        return std::nullopt;
    }
    return jobs;
}

int run_render(const RenderArgs& a) {
    if (!check_tolerance("render", a.flatten.tolerance)) return kExitBadInput;
    if (a.inputs.empty() && a.from_list.empty()) {
        std::fprintf(stderr, "casteljau render: no input: give SVG files, or --from-list FILE\n");
        return kExitBadInput;
    }
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
    std::optional<std::vector<RenderJob>> jobs = gather_inputs(a);
    if (!jobs) return kExitBadInput;
    // A list may hold any number of files, one among them: always a folder.
    const bool to_folder = a.inputs.size() > 1 || !a.from_list.empty() ||
                           (!a.output.empty() && a.output.back() == '/');
    if (to_folder) {
        std::error_code ec;
        fs::create_directories(a.output, ec);
        if (ec) {
            std::fprintf(stderr, "casteljau render: -o %s: cannot create the folder: %s\n",
                         a.output.c_str(), ec.message().c_str());
            return kExitFailure;
        }
    }
    plan_outputs(*jobs, a.output, to_folder);
    // Records go to stdout as they come (a pipeline sees each file when it
    // and those before it are done), to a file at the end (written whole).
    std::string stats;
    const RecordSink sink = [&](const std::string& record) {
        if (a.stats == "-") {
            std::fputs((record + "\n").c_str(), stdout);
            std::fflush(stdout);
        } else {
            stats += record + "\n";
        }
    };
    int status = render_batch(a, background, *jobs, to_folder && ::isatty(2), sink);
    if (!a.stats.empty() && a.stats != "-") { // also when empty: no stale file from an earlier run
        if (const std::string err = write_file_atomic(a.stats, stats); !err.empty()) {
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
    // Not CLI::ExistingFile: a missing file among many fails alone (checked_job).
    cmd->add_option("inputs", a->inputs, "SVG files");
    cmd->add_option("--from-list", a->from_list,
                    "Also render the SVG files listed in FILE, one path a line (- for the "
                    "standard input); the output is then a folder");
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
                    "Threads (default: all cores): files at once, and bands of rows of a file; the "
                    "output is the same")
        ->check(CLI::Range(1, 1024));
    const std::map<std::string, RenderArgs::Pixels> pixels{{"auto", RenderArgs::Pixels::automatic},
                                                           {"float", RenderArgs::Pixels::float32},
                                                           {"u8", RenderArgs::Pixels::u8}};
    cmd->add_option("--pixels", a->pixels,
                    "auto (default: u8 for 8-bit files, float for EXR and TIFF), float (exact "
                    "compositing) or u8 (8 bits a channel, rounded at each composite as Cairo "
                    "does; a quarter of the memory, faster)")
        ->transform(CLI::CheckedTransformer(pixels, CLI::ignore_case));
    cmd->add_option("--repeat", a->repeat,
                    "Render the parsed scene N times; stage times are medians")
        ->check(CLI::Range(1, kMaxRepeat));
    cmd->add_option("--stats", a->stats,
                    "Write timing and error statistics as JSON to FILE, or - for stdout");
    return [a] { return run_render(*a); };
}

} // namespace casteljau::cli
