// The subpaths a stroke outlines: the visible part of a path, or its
// dashes (stroke/detail/pieces.h).
#include "casteljau/stroke/detail/pieces.h"

#include "casteljau/flatten/flatten.h"
#include "casteljau/geom/line_clip.h"

#include <cmath>
#include <type_traits>

namespace casteljau::stroke_detail {

namespace {

// Dash boundaries walked per path (stroker.h): beyond, the path is stroked
// solid, as Skia (Chrome, Firefox) strokes a dash pattern of more than a
// million dashes; a pattern so fine is a solid line to the eye, and its
// dots' outlines took 700 MB ("0 1e-6" on a line 120 px long).
constexpr std::size_t kMaxDashes = 1 << 20;

// A position in the dash pattern: entry k (even: a dash, odd: a gap) with
// `remaining` of its length left.
struct DashCursor {
    const std::vector<double>& pattern; // even length, positive sum
    double period;
    std::size_t k = 0;
    double remaining;

    // Where a subpath starts: the offset, wrapped into [0, period) (negative too).
    DashCursor(const std::vector<double>& p, double per, double offset)
        : pattern(p), period(per), remaining(p[0]) {
        double phase = std::fmod(offset, period);
        if (phase < 0) phase += period;
        consume(phase);
    }
    bool in_dash() const { return k % 2 == 0; }
    void next() {
        k = (k + 1) % pattern.size();
        remaining = pattern[k];
    }
    // Moves `len` along, whole periods at once: O(pattern length) for any
    // length. An infinite one (a chord between points 1e308 apart, whose
    // length overflows) leaves the phase as it is rather than make it NaN.
    void skip(double len) {
        if (!std::isfinite(len)) return;
        if (len < remaining) return void(remaining -= len);
        len -= remaining;
        next();
        consume(std::fmod(len, period));
    }

    // Whether a zero-length dash (0 in the array: a dot with round or square
    // caps) starts where the walk stands: the walk passes a boundary only when
    // it goes beyond it, so a dot at a subpath's end is found here.
    bool at_dot() {
        for (std::size_t turns = 0; remaining == 0 && turns <= pattern.size(); ++turns) {
            if (in_dash() && pattern[k] == 0) return true;
            next();
        }
        return false;
    }

  private:
    // Moves `len` along. A boundary exactly at `len` is passed unless a
    // zero-length dash starts there: that dash stays current, so that a dot
    // at a subpath's start is drawn (SVG 2 draws every zero-length dash's
    // caps; a dash ending there has none).
    void consume(double len) { // len < period: ends within one turn of the pattern
        while (len > remaining || (len == remaining && remaining > 0)) len -= remaining, next();
        remaining -= len;
    }
};

} // namespace

void dashed(const Path& path, const StrokeGeometry& st, double tol, const Rect& keep,
            DashBuffers& buffers, Pieces& out, Growth& growth) {
    std::vector<double>& pattern = buffers.pattern;
    pattern.assign(st.dashes.begin(), st.dashes.end());
    if (pattern.size() % 2) pattern.insert(pattern.end(), st.dashes.begin(), st.dashes.end());
    double period = 0;
    for (double d : pattern) period += d;
    if (!(period > 0)) { // all zero: solid (SVG 1.1, 11.4)
        for (const Subpath& sp : path.subpaths()) out.add(sp);
        return;
    }
    std::size_t walked = 0;
    const std::size_t runs_before = out.runs.size(), segments_before = out.segments.size();
    const auto solid = [&] {
        out.runs.resize(runs_before), out.segments.resize(segments_before), out.open = false;
        visible_part(path, keep, out, growth);
    };
    std::vector<FlatVertex>& v = buffers.vertices;
    for (const Subpath& sp : path.subpaths()) {
        DashCursor dash(pattern, period, st.dash_offset);
        bool open = false; // the last emitted dash continues into this piece
        const std::size_t first = out.runs.size();
        bool from_start = false; // the first dash starts at the subpath's start
        const auto emit = [&](const Segment& seg, double ta, double tb) {
            const Segment piece = segment_subsegment(seg, ta, tb);
            if (!segment_control_bounds(piece).intersects(keep)) return void(open = false);
            if (!open && out.runs.size() == first)
                from_start = ta == 0 && &seg == &sp.segments.front();
            if (!open) out.move_to(segment_start(piece));
            out.append(piece);
            if (ta == tb) { // a zero-length dash: its caps face the path's way there
                const Vec2 d = tb < 1 ? segment_start_tangent(segment_subsegment(seg, ta, 1.0))
                                      : segment_end_tangent(seg);
                if (const double len = d.length(); len > 0) out.runs.back().along = d / len;
            }
            growth.reached(out.segments.size());
            open = true;
        };
        for (const Segment& seg : sp.segments) {
            v.assign(1, {segment_start(seg), 0.0});
            std::visit(
                [&](const auto& c) {
                    flatten_curve(c, FlattenOptions{tol * 1e-3, FlattenMethod::Adaptive, 0},
                                  [&](const FlatVertex& x) {
                                      growth.reached(v.size());
                                      v.push_back(x);
                                  });
                },
                seg);
            double t_from = 0;
            // Passes `len` out of reach: the dash in progress ends at t_end,
            // and the next one can only start after it (at t_after).
            const auto pass = [&](double t_end, double len, double t_after) {
                if (dash.in_dash() && t_from < t_end) emit(seg, t_from, t_end);
                open = false;
                dash.skip(len);
                t_from = t_after;
            };
            for (std::size_t i = 1; i < v.size() && walked < kMaxDashes; ++i) {
                const Point a = v[i - 1].p, b = v[i].p;
                const double len = distance(a, b);
                const auto t_at = [&](double pos) {
                    return pos >= len ? v[i].t : v[i - 1].t + (v[i].t - v[i - 1].t) * (pos / len);
                };
                // The stretch [s0, s1] of the chord within reach (clipped when
                // it leaves the box: a chord of a curve reaching 1e308 is long;
                // one whose length overflows is passed over whole).
                if (!std::isfinite(len)) {
                    pass(v[i - 1].t, len, v[i].t);
                    continue;
                }
                // The walk measures from s0 along the stretch, whose length is
                // taken between the clipped ends: on a chord 1e17 long s0 and
                // s1 are multiples of 16 (their ulp), where s1 - s0 would be
                // off by that much and s0 + 4 would not move (a walk that
                // stood still emitted 2^19 dots at one point).
                double s0 = 0, s1 = len, stretch = len;
                if (!keep.contains(a) || !keep.contains(b)) {
                    const auto part = clip_line(a, b, keep);
                    s0 = part ? distance(a, part->front()) : len;
                    s1 = part ? distance(a, part->back()) : len;
                    stretch = part ? distance(part->front(), part->back()) : 0;
                }
                if (s0 > 0) pass(v[i - 1].t, s0, t_at(s0));
                double walk = 0;
                while (stretch - walk > dash.remaining && walked < kMaxDashes) {
                    walk += dash.remaining; // the pattern changes in this chord
                    const double t = t_at(s0 + walk);
                    if (dash.in_dash()) emit(seg, t_from, t);
                    open = false;
                    t_from = t;
                    dash.next();
                    ++walked;
                }
                dash.remaining -= stretch - walk;
                if (s1 < len) pass(t_at(s1), len - s1, v[i].t);
            }
            if (walked >= kMaxDashes) return solid();
            if (dash.in_dash() && t_from < 1) emit(seg, t_from, 1.0);
        }
        if (sp.closed && open && from_start) out.rejoin(first); // a dash through the start
        if (!sp.segments.empty() && dash.at_dot()) {            // a dot at the subpath's end
            open = false;
            emit(sp.segments.back(), 1.0, 1.0);
        }
    }
}

// The parts of `path` within `keep`: a segment
// whose control box misses `keep` is left out and its subpath is cut there
// (the cut ends lie out of reach, so their caps cannot show); a line is
// clipped to `keep`; a curve larger than 4 box sizes is halved until its
// pieces are small or miss, and a piece still large at kCullDepth is taken
// as its chord, clipped. So strokes of curves reaching 1e308 cost what their
// visible part costs, and the outline never measures a length beyond it
// (whose square would overflow). A closed subpath cut so keeps its closing
// join: its part ending at its start goes on into the part starting there.
// (It had caps there instead, where the renderer's strip of rows cut it
// elsewhere; and a line wholly outside did not count as a cut, so the
// parts were closed with a line across the drawing.)
void visible_part(const Path& path, const Rect& keep, Pieces& out, Growth& growth) {
    const double small = 4 * std::max(keep.width(), keep.height());
    for (const Subpath& sp : path.subpaths()) {
        bool open = false, cut = false; // cut: a part of it has been left out
        const std::size_t first = out.runs.size();
        bool from_start = false; // the first part starts at the subpath's start
        const auto keep_piece = [&](const Segment& piece) {
            if (!open && out.runs.size() == first) from_start = !cut;
            if (!open) out.move_to(segment_start(piece));
            out.append(piece);
            growth.reached(out.segments.size());
            open = true;
        };
        const auto keep_line = [&](Point a, Point b) {
            const auto part = clip_line(a, b, keep);
            if (!part) {
                open = false, cut = true;
                return;
            }
            if (part->front() != a) open = false, cut = true; // before from_start is taken
            keep_piece(Line{{part->front(), part->back()}});
            if (part->back() != b) open = false, cut = true;
        };
        for (const Segment& seg : sp.segments) {
            std::visit(
                [&](const auto& curve) {
                    using Curve = std::decay_t<decltype(curve)>;
                    if constexpr (std::is_same_v<Curve, Line>)
                        return keep_line(curve.start(), curve.end());
                    cull_walk(curve, [&](const Curve& c, int depth) {
                        const Rect box = c.control_bounds();
                        if (!box.intersects(keep)) {
                            open = false, cut = true;
                        } else if (box.width() <= small && box.height() <= small) {
                            keep_piece(c);
                        } else if (depth == kCullDepth) {
                            keep_line(c.start(), c.end());
                        } else {
                            return true;
                        }
                        return false;
                    });
                },
                seg);
        }
        if (sp.closed && open && from_start) out.rejoin(first);
        out.open = false;
    }
}

} // namespace casteljau::stroke_detail
