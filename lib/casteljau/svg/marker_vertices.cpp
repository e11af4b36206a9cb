#include "casteljau/svg/marker_vertices.h"

#include <cmath>
#include <numbers>

namespace casteljau {

namespace {

double degrees(Vec2 v) { return std::atan2(v.y, v.x) * 180 / std::numbers::pi; }

// The mean of two directions' angles across the smaller arc between them.
double bisector_deg(Vec2 in, Vec2 out) {
    const double a = degrees(in), b = degrees(out);
    double mean = (a + b) / 2;
    if (std::fabs(b - a) > 180) mean += 180;
    return mean;
}

// The start (or end) tangent of segment i, or of the nearest segment of
// nonzero length after (before) it in the chain; zero when there is none.
Vec2 out_direction(const std::vector<Segment>& segs, std::size_t i) {
    for (; i < segs.size(); ++i)
        if (const Vec2 t = segment_start_tangent(segs[i]); t.length_sq() > 0) return t;
    return {};
}
Vec2 in_direction(const std::vector<Segment>& segs, std::size_t i) {
    for (std::size_t k = i + 1; k-- > 0;)
        if (const Vec2 t = segment_end_tangent(segs[k]); t.length_sq() > 0) return t;
    return {};
}

} // namespace

std::vector<MarkerVertex> marker_vertices(const Path& path) {
    std::vector<MarkerVertex> out;
    for (const Subpath& sp : path.subpaths()) {
        const std::vector<Segment>& segs = sp.segments;
        if (segs.empty()) continue;
        const std::size_t n = segs.size();
        // Subpath start: in from the closing segment when closed.
        const Vec2 first_out = out_direction(segs, 0);
        const Vec2 last_in = in_direction(segs, n - 1);
        const Vec2 start_in = sp.closed ? last_in : first_out;
        out.push_back({sp.start,
                       bisector_deg(start_in.length_sq() > 0 ? start_in : first_out, first_out),
                       MarkerSlot::Mid});
        for (std::size_t i = 0; i < n; ++i) {
            Vec2 in = in_direction(segs, i);
            Vec2 next = i + 1 < n ? out_direction(segs, i + 1) : Vec2{};
            if (i + 1 == n) next = sp.closed ? first_out : in;
            if (in.length_sq() == 0) in = next;
            if (next.length_sq() == 0) next = in;
            out.push_back({segment_end(segs[i]), bisector_deg(in, next), MarkerSlot::Mid});
        }
    }
    if (!out.empty()) {
        out.front().slot = MarkerSlot::Start;
        out.back().slot = MarkerSlot::End;
    }
    return out;
}

} // namespace casteljau
