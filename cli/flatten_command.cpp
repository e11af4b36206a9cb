// `casteljau flatten --path DATA [--tolerance PX]
//                    [--flatten integral|guided|adaptive|uniform|halving] [--segments N] [--json]`
// Flattens SVG path data (user units = device pixels) and reports the segment
// count, the measured maximum error and the flattening time per curve.
#include "casteljau/curve/path_data.h"
#include "casteljau/flatten/path_flatten.h"
#include "commands.h"
#include "common.h"
#include "json.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace casteljau::cli {

namespace {

// Timing repeats the flattening until this much time has passed, so short
// paths are timed over many runs instead of one clock tick.
constexpr double kMinTimingSeconds = 0.02;

struct FlattenArgs {
    std::string path_data;
    FlattenOptions flatten;
    bool json = false;
};

double time_per_curve_ns(const Path& path, const FlattenOptions& options) {
    using clock = std::chrono::steady_clock;
    std::vector<Polyline> out;
    std::size_t runs = 0;
    const auto start = clock::now();
    double elapsed = 0;
    do {
        out.clear();
        flatten_path(path, Affine::identity(), options, out);
        ++runs;
        elapsed = std::chrono::duration<double>(clock::now() - start).count();
    } while (elapsed < kMinTimingSeconds);
    const double curves = double(std::max<std::size_t>(path.segment_count(), 1));
    return elapsed * 1e9 / (double(runs) * curves);
}

int run_flatten(const FlattenArgs& a) {
    if (!check_tolerance("flatten", a.flatten.tolerance)) return kExitBadInput;
    const PathDataResult parsed = parse_path_data(a.path_data);
    if (parsed.error) {
        std::fprintf(stderr, "casteljau flatten: --path: at offset %zu: %s\n  %s\n  %*s^\n",
                     parsed.error->offset, parsed.error->message.c_str(), a.path_data.c_str(),
                     int(parsed.error->offset), "");
        return kExitBadInput;
    }
    const FlattenOptions& options = a.flatten;
    std::vector<Polyline> lines;
    const FlattenStats stats = flatten_path(parsed.path, Affine::identity(), options, lines, true);
    const double ns = time_per_curve_ns(parsed.path, options);

    if (!a.json) {
        std::printf("segments %zu, max error %.6g px, %.1f ns per curve\n", stats.segments_out,
                    stats.max_error, ns);
        for (const Polyline& l : lines) {
            std::printf("%s\n", l.closed ? "closed" : "open");
            for (const Point& p : l.points) std::printf("  %.17g %.17g\n", p.x, p.y);
        }
        return kExitOk;
    }
    std::string out = "{\"segments\": " + std::to_string(stats.segments_out) +
                      ", \"max_error_px\": " + json_number(stats.max_error) +
                      ", \"ns_per_curve\": " + json_number(ns) + ", \"points\": [";
    std::string subpaths = "[";
    std::size_t index = 0;
    for (const Polyline& l : lines) {
        if (index > 0) subpaths += ", ";
        subpaths += "{\"first\": " + std::to_string(index) +
                    ", \"count\": " + std::to_string(l.points.size()) +
                    ", \"closed\": " + (l.closed ? "true" : "false") + "}";
        for (const Point& p : l.points) {
            out += (index++ > 0 ? ", [" : "[") + json_number(p.x) + ", " + json_number(p.y) + "]";
        }
    }
    out += "], \"subpaths\": " + subpaths + "]}";
    std::printf("%s\n", out.c_str());
    return kExitOk;
}

} // namespace

Command add_flatten_command(CLI::App& app) {
    auto args = std::make_shared<FlattenArgs>();
    CLI::App* cmd = app.add_subcommand(
        "flatten", "Flatten SVG path data into line segments and measure the error");
    cmd->add_option("--path", args->path_data, "SVG path data, e.g. 'M0 0 C 50 100 150 -100 200 0'")
        ->required();
    add_flatten_options(cmd, args->flatten);
    cmd->add_flag("--json", args->json,
                  "Print {\"segments\", \"max_error_px\", \"ns_per_curve\", \"points\"} as JSON");
    return [args] { return run_flatten(*args); };
}

} // namespace casteljau::cli
