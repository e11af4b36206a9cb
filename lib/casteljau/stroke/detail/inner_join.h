// Internal to the stroker (not installed): the inner side of a join.
//
// The inner side of a join runs ..., A, p, B, ... through the joint p, from
// the offsets of the segment before it to those of the segment after it.
// Through p, that side goes round the square where the two segments' bands
// overlap a second time, and there the outline's winding is 2: exact-area
// coverage adds the winding over a pixel before clamping it to 1, so a
// pixel at an inner corner would get 1 where the stroke covers 3/4 of it.
// Where the two offsets cross, at X, the loop X ... A p B ... X is cut out
// (stroker.h gives the whole construction and what stays approximate).
#pragma once

#include "casteljau/geom/point.h"

#include <cstddef>
#include <span>
#include <vector>

namespace casteljau::stroke_detail {

// Edges searched on each side of an inner joint (stroker.h: the inner side
// of a join). A line meets the next line on its first edge; curves sampled
// more finely take a few. Bounds the search to kMeetEdges^2 tests where the
// offsets do not meet.
inline constexpr std::size_t kMeetEdges = 64;

// A point of a sampled segment and its unit tangent.
struct Sample {
    Point p;
    Vec2 d;                   // unit tangent
    bool cusp_before = false; // the normal flips just before this sample
};

// The segments on either side of an inner joint: the samples of the one
// before it (its last ones at least) and after it (its first ones at
// least), and how far from them a point is in their bands: h, and tol for
// the sampling.
struct Neighbours {
    std::span<const Sample> before, after;
    double reach;
};

// Cuts the loop at the inner joint side[joint] (the segment before it from
// side[begin]): returns where the segment after the joint now begins on this
// side, X, or B when the offsets do not cross.
std::size_t meet(std::vector<Point>& side, std::size_t begin, std::size_t joint,
                 const Neighbours& n);

// meet() for the join that closes a subpath: the joint is the side's last
// point, and the segment after it is the first, side[0, first_end).
void meet_closing(std::vector<Point>& side, std::size_t begin, std::size_t first_end,
                  const Neighbours& n);

} // namespace casteljau::stroke_detail
