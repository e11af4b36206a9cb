// The inner side of a join: where the offsets of the segments on either side
// of an inner joint cross, and the loop cut out there (detail/inner_join.h).
#include "casteljau/stroke/detail/inner_join.h"

#include <algorithm>
#include <limits>
#include <optional>

namespace casteljau::stroke_detail {

namespace {

// Where the segments p0 p1 and q0 q1 cross (their ends included), if they do.
std::optional<Point> crossing(Point p0, Point p1, Point q0, Point q1) {
    const Vec2 r = p1 - p0, s = q1 - q0, w = q0 - p0;
    const double den = r.cross(s);
    const double t = w.cross(s) / den, u = w.cross(r) / den;
    // Parallel edges (den = 0) give no finite t, nor does NaN geometry.
    if (!(t >= 0 && t <= 1 && u >= 0 && u <= 1)) return std::nullopt;
    return p0 + r * t;
}

// Whether every point of q lies within r of the polyline through c's points.
bool within(std::span<const Point> q, std::span<const Sample> c, double r) {
    for (const Point x : q) {
        double d = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k + 1 < c.size(); ++k)
            d = std::min(d, distance_to_segment(x, c[k].p, c[k + 1].p));
        if (!(d <= r)) return false;
    }
    return true;
}

struct Meeting {
    std::size_t i, j; // edges back from the joint, on from it
    Point x;
};

// The crossing nearest the joint (least i + j, then least i) of the edges
// (side[a - i - 1], side[a - i]), i < ni, before it and (side[b + j],
// side[b + j + 1]), j < nj, after it, among the pairs `allowed`. None if the
// offsets it cuts out, side[a - i, a] and side[b, b + j], do not lie in the
// other segment's band (next to the joint: a side point is the offset of a
// sample, one for one but for cusps): then the loop they close is not the
// bands' overlap but goes round more, as where the path comes back across
// itself and the offsets cross again, round a hole of the stroke.
template <class Allowed>
std::optional<Meeting> meeting(const std::vector<Point>& side, std::size_t a, std::size_t ni,
                               std::size_t b, std::size_t nj, const Neighbours& n,
                               Allowed allowed) {
    ni = std::min(ni, kMeetEdges), nj = std::min(nj, kMeetEdges);
    const std::span<const Point> pts(side);
    for (std::size_t sum = 0; sum + 1 < ni + nj; ++sum)
        for (std::size_t i = sum < nj ? 0 : sum - nj + 1; i <= sum && i < ni; ++i) {
            const std::size_t j = sum - i;
            if (!allowed(i, j)) continue;
            const auto x = crossing(side[a - i - 1], side[a - i], side[b + j], side[b + j + 1]);
            if (!x) continue;
            if (!within(pts.subspan(a - i, i + 1), n.after.first(std::min(n.after.size(), j + 2)),
                        n.reach) ||
                !within(pts.subspan(b, j + 1), n.before.last(std::min(n.before.size(), i + 2)),
                        n.reach))
                return std::nullopt;
            return Meeting{i, j, *x};
        }
    return std::nullopt;
}

} // namespace

// The inner side of a join runs ..., A, p, B, ... through the joint p at
// `joint`, from the offsets of the segment before it (from `begin`) to those
// of the segment after it (to the end). Where they cross, at X, the loop
// X ... A p B ... X, which goes round the part of the two segments' bands
// that overlaps, is cut out. Returns where the segment after the joint now
// begins on this side: X, or B.
std::size_t meet(std::vector<Point>& side, std::size_t begin, std::size_t joint,
                 const Neighbours& n) {
    const std::size_t a = joint - 1, b = joint + 1;
    const auto m = meeting(side, a, a - begin, b, side.size() - 1 - b, n,
                           [](std::size_t, std::size_t) { return true; });
    if (!m) return b;
    const std::size_t x = a - m->i;
    side[x] = m->x;
    side.erase(side.begin() + std::ptrdiff_t(x + 1), side.begin() + std::ptrdiff_t(b + m->j + 1));
    return x;
}

// meet() for the join that closes a subpath: the joint is the side's last
// point, and the segment after it is the first, side[0, first_end). At
// least two points besides X are kept (the two offsets are one curve's
// when the subpath has one segment).
void meet_closing(std::vector<Point>& side, std::size_t begin, std::size_t first_end,
                  const Neighbours& n) {
    const std::size_t a = side.size() - 2;
    const auto m = meeting(side, a, a - begin, 0, first_end - 1, n,
                           [&](std::size_t i, std::size_t j) { return j + 2 < a - i; });
    if (!m) return;
    side.resize(a - m->i);
    side.push_back(m->x);
    side.erase(side.begin(), side.begin() + std::ptrdiff_t(m->j + 1));
}

} // namespace casteljau::stroke_detail
