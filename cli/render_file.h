// Rendering one input of `casteljau render`: parse, render (--repeat times),
// encode, and its --stats record. A FileRenderer keeps its band renderer and
// canvases from file to file: a batch worker renders its files with one.
#pragma once

#include "canvas_budget.h"
#include "casteljau/paint/canvas.h"
#include "casteljau/render/bands.h"
#include "common.h"
#include "render_inputs.h"

#include <string>
#include <vector>

namespace casteljau::cli {

struct RenderArgs {
    std::vector<std::string> inputs;
    std::string from_list;
    std::string output;
    double width = 0, height = 0, scale = 0;
    FlattenOptions flatten;
    SvgOptions svg;
    bool antialias = true;
    bool linear_light = false;
    std::string background;
    int threads = 0;
    // --pixels: the canvas drawn on. Auto (the default): 8 bits a channel
    // for 8-bit files (PNG, JPEG), float for the float ones (EXR, TIFF).
    enum class Pixels { automatic, float32, u8 } pixels = Pixels::automatic;
    int repeat = 1;
    std::string stats;
};

/// --threads, or every core.
int all_threads(const RenderArgs& a);

/// What one file gave.
struct FileOutcome {
    int status = 0;
    Messages log;
    std::string record; ///< its --stats JSON object (no newline), when asked
};

/// Renders files one after the other, reusing its buffers.
class FileRenderer {
  public:
    FileRenderer(const RenderArgs& a, Premul background) : a_(a), background_(background) {}

    /// Renders `job` on `threads` band threads. The frame's memory is held
    /// from `budget` while it is drawn.
    FileOutcome render(const RenderJob& job, int threads, CanvasBudget& budget);

  private:
    template <class Pixel>
    void render_into(const RenderJob& job, int threads, BasicCanvas<Pixel>& canvas,
                     CanvasBudget& budget, FileOutcome& out);

    const RenderArgs& a_;
    Premul background_;
    BandRenderer renderer_;
    Canvas canvas_;
    Canvas8 canvas8_;
    Renderer measure_; ///< the untimed pass that counts segments and errors
    Canvas scratch_;
};

} // namespace casteljau::cli
