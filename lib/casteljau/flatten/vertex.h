// FlatVertex: one vertex of a flattened curve and the curve parameter it sits at.
// Every flattener emits the vertices after the curve's start, in order, ending
// with the curve's end point at t = 1 (bit for bit, so joined curves stay joined).
#pragma once

#include "casteljau/geom/point.h"

namespace casteljau {

/// A vertex of a flattened curve and the curve parameter it lies at.
struct FlatVertex {
    Point p;
    double t = 0;
    /// Exact equality of every member.
    constexpr bool operator==(const FlatVertex&) const = default;
};

} // namespace casteljau
