#include "render_file.h"

#include "casteljau/io/canvas_write.h"
#include "casteljau/io/image_write.h"
#include "casteljau/render/output_size.h"
#include "commands.h"
#include "json.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <thread>

namespace casteljau::cli {

namespace {

using Clock = std::chrono::steady_clock;

// Frames up to this size (a 2048 x 2048 float canvas) are kept for the next
// file, which then allocates nothing; larger ones are freed after their file,
// so that a worker does not hold a large frame the budget no longer counts.
constexpr std::size_t kKeepCanvasBytes = std::size_t(64) << 20;

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The fields every record starts with, failed or not.
std::string record_head(const RenderJob& job, const FileOutcome& out) {
    std::string r = "{\"input\": " + json_string(job.input) +
                    ", \"output\": " + json_string(job.output) +
                    ", \"status\": " + std::to_string(out.status);
    if (!out.log.error.empty()) r += ", \"error\": " + json_string(out.log.error);
    return r + ", \"warnings\": " + std::to_string(out.log.warnings);
}

} // namespace

namespace {

// The 8-bit canvas for an 8-bit file: a quarter of the memory traffic, and
// each composite rounded once to the 8 bits the file keeps (within 0.2/255
// of the float canvas on the examples, bench/README.md). Float files keep
// the float canvas, which an 8-bit one would band.
bool draws_u8(const RenderArgs& a, const std::string& output) noexcept {
    if (a.pixels != RenderArgs::Pixels::automatic) return a.pixels == RenderArgs::Pixels::u8;
    return !stores_float(output);
}

} // namespace

int all_threads(const RenderArgs& a) {
    return a.threads > 0 ? a.threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

FileOutcome FileRenderer::render(const RenderJob& job, int threads, CanvasBudget& budget) {
    FileOutcome out;
    const auto t0 = Clock::now();
    try {
        if (!job.error.empty()) {
            out.status = kExitBadInput;
            out.log.fail(job.error);
        } else if (draws_u8(a_, job.output)) {
            render_into(job, threads, canvas8_, budget, out);
        } else {
            render_into(job, threads, canvas_, budget, out);
        }
    } catch (const std::exception& e) { // out of memory: this file fails, the others go on
        out.status = kExitFailure;
        out.log.fail(job.input + ": " + e.what());
    }
    if (!a_.stats.empty() && out.record.empty())
        out.record =
            record_head(job, out) + ", \"total_ms\": " + json_number(ms(Clock::now() - t0)) + "}";
    return out;
}

template <class Pixel>
void FileRenderer::render_into(const RenderJob& job, int threads, BasicCanvas<Pixel>& canvas,
                               CanvasBudget& budget, FileOutcome& out) {
    const auto t0 = Clock::now();
    SvgOptions svg = a_.svg;
    svg.media_size = {a_.width, a_.height, a_.scale}; // what @media width and height answer
    const std::optional<Scene> loaded = load_svg(job.input, svg, out.status, out.log);
    if (!loaded) return;
    const Scene& scene = *loaded;
    const double parse_ms = ms(Clock::now() - t0);
    const OutputSize size = output_size(scene.width, scene.height, {a_.width, a_.height, a_.scale});
    if (!size.error.empty()) {
        out.log.fail(job.input + ": " + size.error);
        out.status = kExitBadInput;
        return;
    }
    const double s = size.scale;
    const int w = size.width, h = size.height;
    const bool stats = !a_.stats.empty();
    const std::size_t frame_bytes = std::size_t(w) * std::size_t(h) * sizeof(Pixel);
    const std::size_t scratch_bytes = stats ? std::size_t(w) * std::size_t(h) * sizeof(Premul) : 0;
    const CanvasBudget::Hold hold(budget, frame_bytes + scratch_bytes);
    const RenderOptions options{.flatten = a_.flatten,
                                .antialias = a_.antialias,
                                .linear_light_gradients = a_.linear_light,
                                .time_stages = stats};
    std::vector<double> flatten_ms, raster_ms, frame_ms;
    RenderStats rs;
    for (int i = 0; i < a_.repeat; ++i) {
        const auto f0 = Clock::now();
        canvas.resize(w, h); // the renderer clears each band to the background
        rs = renderer_.render(scene, Affine::scale(s), canvas, options, background_, threads);
        frame_ms.push_back(ms(Clock::now() - f0));
        flatten_ms.push_back(rs.flatten_ms);
        raster_ms.push_back(rs.raster_ms);
    }
    const auto e0 = Clock::now();
    const std::string err = write_canvas_atomic(job.output, canvas);
    const double encode_ms = ms(Clock::now() - e0);
    const double total_ms = ms(Clock::now() - t0);
    if (frame_bytes > kKeepCanvasBytes) canvas = BasicCanvas<Pixel>{};
    if (!err.empty()) {
        out.log.fail(err);
        out.status = kExitFailure;
        return;
    }
    if (!stats) return;
    // Segment counts and the exact flattening error, from a separate, untimed
    // single-band pass (bands repeat the flattening of shapes they share).
    scratch_.reset(w, h);
    const RenderStats m =
        measure_.render(scene, Affine::scale(s), scratch_,
                        {.flatten = a_.flatten, .antialias = a_.antialias, .measure_error = true});
    if (scratch_bytes > kKeepCanvasBytes) scratch_ = Canvas{};
    out.record =
        record_head(job, out) + ", \"segments_in\": " + std::to_string(m.flatten.curves_in) +
        ", \"segments_out\": " + std::to_string(m.flatten.segments_out) +
        ", \"max_error_px\": " + json_number(m.flatten.max_error) +
        ", \"parse_ms\": " + json_number(parse_ms) +
        ", \"flatten_ms\": " + json_number(median(flatten_ms)) +
        ", \"raster_ms\": " + json_number(median(raster_ms)) +
        ", \"encode_ms\": " + json_number(encode_ms) +
        ", \"frame_ms\": " + json_number(median(frame_ms)) +
        ", \"total_ms\": " + json_number(total_ms) + ", \"width\": " + std::to_string(w) +
        ", \"height\": " + std::to_string(h) + ", \"threads\": " + std::to_string(threads) +
        ", \"pixels\": " + (draws_u8(a_, job.output) ? "\"u8\"" : "\"float\"") +
        ", \"repeat\": " + std::to_string(a_.repeat) + "}";
}

} // namespace casteljau::cli
