// Flattening a whole Path into device-space polylines.
//
// Each segment is first mapped to device space by the path's transform (the
// curves are affine invariant, so mapping control points is exact), then
// flattened there, so the tolerance is in device pixels whatever the
// transform. Lines pass through unchanged. A closed subpath gives a closed
// polyline whose last vertex equals its first.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/flatten/flatten.h"

#include <cstddef>
#include <vector>

namespace casteljau {

/// A flattened subpath: its vertices, and whether it is closed.
struct Polyline {
    std::vector<Point> points;
    bool closed = false;
};

/// Counts and errors of a flattening, for --stats and the benchmarks.
struct FlattenStats {
    std::size_t curves_in = 0;    ///< segments of the path, lines included
    std::size_t segments_out = 0; ///< polyline edges
    /// Deepest equivalent subdivision level: ceil(log2(1 / shortest parameter step)).
    int max_depth = 0;
    double max_error = 0; ///< device px; measured only when asked for
};

/// Appends one polyline per subpath to `out`. With `measure_error` the exact
/// error measure of error.h is taken on every curve (costly: for stats and tests).
FlattenStats flatten_path(const Path& path, const Affine& to_device, const FlattenOptions& options,
                          std::vector<Polyline>& out, bool measure_error = false);

} // namespace casteljau
