// Arc length along a path: the point and direction at a distance from its
// start, for text on a path (SVG 2, 11.8.3 "textPath") and for anything
// else that walks a path by length.
//
// The path is flattened once to a polyline within `tolerance` of it (in the
// path's own units) and lengths are measured along that polyline: a chord
// of a curve within distance e of it is shorter than the arc by O(e^2 / l)
// per chord of length l, so the measured length converges quadratically as
// the tolerance shrinks. Subpaths follow one another: distances run over
// all of them, the jump between two subpaths taking no length.
#pragma once

#include "casteljau/curve/path.h"

#include <optional>
#include <vector>

namespace casteljau {

/// Lengths along a path, flattened once (see above).
class PathMeasure {
  public:
    /// Flattens `path` within `tolerance`, in its own units (> 0).
    PathMeasure(const Path& path, double tolerance);
    /// The length of all its subpaths together.
    double length() const { return total_; }
    /// Whether the path is a single closed subpath.
    bool closed() const { return closed_; }
    /// A point on the path and its unit tangent.
    struct Place {
        Point point;
        Vec2 tangent;
    };
    /// The point at `distance` from the start and the unit tangent there;
    /// nullopt outside [0, length()] or on an empty path.
    std::optional<Place> at(double distance) const;

  private:
    struct Vertex {
        Point p;
        double distance; ///< from the path's start
        bool starts_subpath;
    };
    std::vector<Vertex> vertices_;
    double total_ = 0;
    bool closed_ = false;
};

} // namespace casteljau
