// `casteljau patch IN.{bpt,map,json} -o OUT.png [--width W --height H] [--tolerance PX]
//   [--tessellate adaptive|uniform] [--steps N] [--view AZ,EL] [--texture IMG|checker|none]
//   [--wireframe] [--mesh OUT.{obj,ply}] [--background COLOR] [--stats FILE|-]`
//
// Reads the patches, tessellates them for the view (adaptive: within
// --tolerance px on screen; uniform: --steps N per patch side, or without N
// the fewest steps whose measured error meets the tolerance), renders the
// mesh and writes the image (and the mesh). The camera is the file's own
// (.json "camera") unless --view is given; otherwise an orbit view fitted to
// the model at --view AZ,EL (default 35,25).
#include "casteljau/io/atomic_file.h"
#include "casteljau/io/canvas_write.h"
#include "casteljau/io/image_read.h"
#include "casteljau/io/mesh_write.h"
#include "casteljau/io/patch_read.h"
#include "casteljau/render3d/mesh_raster.h"
#include "casteljau/svg/color.h"
#include "casteljau/tessellate/adaptive.h"
#include "casteljau/tessellate/error.h"
#include "casteljau/tessellate/uniform.h"
#include "commands.h"
#include "common.h"
#include "json.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

namespace casteljau::cli {

namespace {

using Clock = std::chrono::steady_clock;

// Limits of the patch command. Tolerances below 0.01 px ask for triangles
// smaller than the z-buffer's samples (1/4 px apart) can tell apart; uniform
// grids are capped at 1024 steps a side and 2^25 triangles in all.
constexpr double kMinPatchTolerance = 0.01;
constexpr int kMaxSteps = 1024;
constexpr double kMaxUniformTriangles = double(1 << 25);

struct PatchArgs {
    std::string input, output, mesh, stats, texture = "checker", background = "white";
    int width = 800, height = 600;
    double tolerance = 0.25;
    bool adaptive = true, wireframe = false;
    int steps = 0;
    std::vector<double> view;
};

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

int fail(int status, const std::string& message) {
    std::fprintf(stderr, "error: %s\n", message.c_str());
    return status;
}

// The options the parser cannot check alone; kExitOk when all are valid.
int check_options(const PatchArgs& a) {
    if (a.tolerance < kMinPatchTolerance || a.tolerance > 1)
        return fail(kExitBadInput, "casteljau patch: --tolerance " + std::to_string(a.tolerance) +
                                       ": must be a number of device pixels in [0.01, 1]");
    if (double(a.width) * a.height > kMaxPixels)
        return fail(kExitBadInput, "casteljau patch: the image is larger than 2^26 pixels");
    if (!parse_color(a.background))
        return fail(kExitBadInput,
                    "casteljau patch: --background '" + a.background + "' is not a color");
    return kExitOk;
}

struct StageTimes {
    double parse = 0, tessellate = 0, raster = 0, encode = 0, total = 0; // ms
};

std::string stats_json(const PatchArgs& a, const PatchModel& model, const Mesh& mesh,
                       const ScreenProjection& view, int steps, const AdaptiveStats& adaptive,
                       const StageTimes& t) {
    return "{\"input\": " + json_string(a.input) + ", \"output\": " + json_string(a.output) +
           ", \"patches\": " + std::to_string(model.patches.size()) +
           ", \"tessellate\": " + json_string(a.adaptive ? "adaptive" : "uniform") +
           ", \"steps\": " + std::to_string(steps) +
           ", \"pieces\": " + std::to_string(adaptive.pieces) +
           ", \"budget_reached\": " + (adaptive.budget_reached ? "true" : "false") +
           ", \"tolerance_px\": " + json_number(a.tolerance) +
           ", \"triangles\": " + std::to_string(mesh.triangles.size()) +
           ", \"vertices\": " + std::to_string(mesh.positions.size()) +
           ", \"max_error_px\": " + json_number(measure_max_error_px(model, mesh, view)) +
           ", \"parse_ms\": " + json_number(t.parse) +
           ", \"tessellate_ms\": " + json_number(t.tessellate) +
           ", \"raster_ms\": " + json_number(t.raster) +
           ", \"encode_ms\": " + json_number(t.encode) + ", \"total_ms\": " + json_number(t.total) +
           ", \"width\": " + std::to_string(a.width) + ", \"height\": " + std::to_string(a.height) +
           "}\n";
}

int run_patch(const PatchArgs& a) {
    const auto t0 = Clock::now();
    if (const int status = check_options(a); status != kExitOk) return status;
    Texture texture;
    if (a.texture != "checker" && a.texture != "none")
        if (const std::string err = texture.load(a.texture); !err.empty())
            // A missing OpenImageIO is the installation's failure, not the input's.
            return fail(openimageio_available() ? kExitBadInput : kExitFailure, "--texture " + err);
    const PatchFile file = read_patch_file(a.input);
    if (!file.model) return fail(file.io_error ? kExitFailure : kExitBadInput, file.error);
    const PatchModel& model = *file.model;
    StageTimes times;
    times.parse = ms(Clock::now() - t0);

    const LookAt camera = file.camera && a.view.empty()
                              ? *file.camera
                              : orbit_view(model.control_bounds(), a.view.empty() ? 35 : a.view[0],
                                           a.view.empty() ? 25 : a.view[1], a.width, a.height);
    const ScreenProjection view = make_projection(camera, a.width, a.height);

    Mesh mesh;
    int steps = a.steps;
    // The most steps that keep the model within the uniform triangle limit.
    const int step_cap = std::min(
        kMaxSteps, int(std::sqrt(kMaxUniformTriangles / (2.0 * double(model.patches.size())))));
    if (!a.adaptive && steps > step_cap)
        return fail(kExitBadInput, "casteljau patch: --steps " + std::to_string(steps) +
                                       " makes more than 2^25 triangles");
    // The search for the equal-tolerance steps is not part of the tessellation time.
    if (!a.adaptive && steps == 0)
        steps = fewest_uniform_steps(model, view, a.tolerance, std::max(1, step_cap), mesh);
    const auto t1 = Clock::now();
    AdaptiveStats adaptive;
    if (a.adaptive) {
        adaptive = tessellate_adaptive(model, view, a.tolerance, mesh);
        if (adaptive.budget_reached)
            std::fprintf(stderr,
                         "warning: %s: adaptive tessellation stopped at its budget of %zu pieces "
                         "(%zu per pixel, at most 2^20); parts of the mesh may be off by more "
                         "than the tolerance (is the camera inside the model?)\n",
                         a.input.c_str(), default_piece_budget(view), kMaxPiecesPerPixel);
    } else
        tessellate_uniform(model, steps, steps, mesh);
    times.tessellate = ms(Clock::now() - t1);

    const auto t2 = Clock::now();
    Canvas canvas(a.width, a.height);
    canvas.fill(premultiply(*parse_color(a.background)));
    MeshRenderer().render(
        mesh, view, {a.texture == "none" ? nullptr : &texture, {0.75f, 0.75f, 0.75f}, a.wireframe},
        canvas);
    times.raster = ms(Clock::now() - t2);

    const auto t3 = Clock::now();
    if (const std::string err = write_canvas_atomic(a.output, canvas); !err.empty())
        return fail(kExitFailure, err);
    times.encode = ms(Clock::now() - t3);
    if (!a.mesh.empty())
        if (const std::string err = write_mesh_atomic(a.mesh, mesh); !err.empty())
            return fail(kExitFailure, err);
    times.total = ms(Clock::now() - t0);
    if (a.stats.empty()) return kExitOk;
    const std::string json = stats_json(a, model, mesh, view, steps, adaptive, times);
    if (a.stats == "-")
        std::fputs(json.c_str(), stdout);
    else if (const std::string err = write_file_atomic(a.stats, json); !err.empty())
        return fail(kExitFailure, "--stats " + err);
    return kExitOk;
}

} // namespace

Command add_patch_command(CLI::App& app) {
    auto a = std::make_shared<PatchArgs>();
    CLI::App* cmd = app.add_subcommand("patch", "Tessellate and render surface patches");
    cmd->add_option("input", a->input, "Patches: .bpt, Quake 3 .map or .json")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", a->output, "Image to write (.png, .tif, .exr, .jpg)")
        ->required();
    cmd->add_option("--width", a->width, "Image width in pixels (default 800)")
        ->check(CLI::Range(1, kMaxSide));
    cmd->add_option("--height", a->height, "Image height in pixels (default 600)")
        ->check(CLI::Range(1, kMaxSide));
    cmd->add_option("--tolerance", a->tolerance,
                    "Largest distance between mesh and surface on screen, px, in [0.01, 1] "
                    "(default 0.25)");
    const std::map<std::string, bool> methods{{"adaptive", true}, {"uniform", false}};
    cmd->add_option("--tessellate", a->adaptive, "adaptive (default) or uniform")
        ->transform(CLI::CheckedTransformer(methods, CLI::ignore_case));
    cmd->add_option("--steps", a->steps,
                    "Uniform only: steps per patch side (default: the fewest that meet the "
                    "tolerance, measured)")
        ->check(CLI::Range(1, kMaxSteps));
    cmd->add_option("--view", a->view, "Azimuth and elevation in degrees, AZ,EL (default 35,25)")
        ->delimiter(',')
        ->expected(2)
        ->check(CLI::Range(-360.0, 360.0));
    cmd->add_option("--texture", a->texture, "checker (default), none, or an image file");
    cmd->add_flag("--wireframe", a->wireframe, "Draw the triangles' edges on top");
    cmd->add_option("--mesh", a->mesh, "Also write the mesh (.obj or .ply)");
    cmd->add_option("--background", a->background, "Background color (default white)");
    cmd->add_option("--stats", a->stats, "Write statistics as JSON to FILE, or - for stdout");
    return [a] { return run_patch(*a); };
}

} // namespace casteljau::cli
