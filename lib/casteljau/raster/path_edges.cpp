#include "casteljau/raster/path_edges.h"

#include "casteljau/flatten/error.h"

#include <algorithm>

namespace casteljau {

namespace {

struct EdgeEmitter {
    EdgeList& edges;
    const FlattenOptions& options;
    FlattenStats& stats;
    bool measure;
    std::vector<FlatVertex> scratch;

    template <class Curve>
    void flatten(const Curve& c) {
        Point a = c.start();
        scratch.clear();
        flatten_curve(c, options, [&](const FlatVertex& v) {
            edges.add_line(a, v.p);
            a = v.p;
            ++stats.segments_out;
            if (measure) scratch.push_back(v);
        });
        if (measure)
            stats.max_error = std::max(stats.max_error, polyline_error(c, c.start(), scratch));
    }

    template <class Curve>
    void cull_and_flatten(const Curve& curve) {
        const PixelRect& clip = edges.clip();
        const double left = clip.x0, upper = clip.y0, right = clip.x1, lower = clip.y1;
        const double rows_top = edges.row_begin(), rows_bottom = edges.row_end();
        // Pieces up to a few clip sizes are flattened whole: culling them
        // further would cost more splits than the segments it saves.
        const double small = 4.0 * std::max(clip.width(), clip.height());
        cull_walk(curve, [&](const Curve& c, int depth) {
            const Rect box = c.control_bounds();
            // Outside the clip, or outside the band of rows asked for. The
            // decisions below depend on the clip only, never on the band, so
            // a band gets exactly the edges the whole frame would.
            if (box.y1 <= upper || box.y0 >= lower || box.x0 >= right) return false;
            if (box.y1 <= rows_top || box.y0 >= rows_bottom) return false;
            const bool inside =
                box.x0 >= left && box.y0 >= upper && box.x1 <= right && box.y1 <= lower;
            if (box.x1 > left && (inside || (box.width() <= small && box.height() <= small))) {
                flatten(c);
                return false;
            }
            // Left of the clip (only its winding counts), or still over 2^40
            // x 4 canvas sizes at the cap (see path_edges.h): the chord.
            if (box.x1 <= left || depth == kCullDepth) {
                edges.add_line(c.start(), c.end());
                ++stats.segments_out;
                return false;
            }
            return true;
        });
    }
};

} // namespace

FlattenStats add_path_edges(const Path& path, const Affine& to_device,
                            const FlattenOptions& options, EdgeList& edges, bool measure_error) {
    FlattenStats stats;
    EdgeEmitter emit{edges, options, stats, measure_error, {}};
    // A path inside the clip and the band: every curve's box is inside too
    // (its control points lie in the path's box), so cull_and_flatten would
    // flatten each whole; going there directly saves its box tests and its
    // walk's copies (glyphs_5k: 6% of the frame, cairo_compare_bench). The
    // one-pixel margin absorbs the rounding between the box's mapped corners
    // and the curves' mapped control points.
    const Rect box = mapped_box(path.control_bounds(), to_device);
    const PixelRect& clip = edges.clip();
    const bool inside = box.x0 >= clip.x0 + 1 && box.x1 <= clip.x1 - 1 &&
                        box.y0 >= std::max(clip.y0, edges.row_begin()) + 1 &&
                        box.y1 <= std::min(clip.y1, edges.row_end()) - 1;
    for (const Subpath& sub : path.subpaths()) {
        for (const Segment& seg : sub.segments) {
            ++stats.curves_in;
            std::visit(
                [&](const auto& c) {
                    const auto dev = c.transformed(to_device);
                    if constexpr (std::is_same_v<std::decay_t<decltype(dev)>, Line>) {
                        edges.add_line(dev.start(), dev.end());
                        ++stats.segments_out;
                    } else if (inside) {
                        emit.flatten(dev);
                    } else {
                        emit.cull_and_flatten(dev);
                    }
                },
                seg);
        }
        if (const auto line = fill_closing_line(sub))
            edges.add_line(to_device * line->start(), to_device * line->end());
    }
    return stats;
}

} // namespace casteljau
