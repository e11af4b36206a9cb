// Edge building: device-space line segments -> clipped, y-ordered edges.
//
// An Edge runs downwards (y0 < y1) and remembers its original direction as
// `dir` (+1 when the segment went down, -1 when it went up): the winding
// contribution. Horizontal segments contribute nothing and are dropped.
//
// Clipping to the canvas [0, W] x [0, H] keeps the coverage exact:
// * y: the part above 0 or below H is cut off (it covers no row).
// * x: the part left of 0 is replaced by its projection onto x = 0 (a vertical
//   edge at the left border: it still changes the winding of every pixel to
//   its right, and a vertical edge at x = 0 covers no pixel area itself), and
//   the part right of W by its projection onto x = W (it changes nothing
//   visible). Segments are split where they cross x = 0 or x = W so that the
//   projected part is exactly the part outside.
// Coordinates are double on input and float after clipping: clipped values lie
// in [0, 16384], where float resolves 2^-10 px, far below 1/255 coverage.
#pragma once

#include "casteljau/geom/point.h"

#include <vector>

namespace casteljau {

struct Edge {
    float x0, y0, x1, y1; // y0 < y1
    float dir;            // +1 or -1
};

class EdgeList {
  public:
    // Starts a new list for a canvas of w x h pixels, keeping the storage.
    void reset(int width, int height);
    // Adds the segment a -> b, clipped. Precondition: finite coordinates.
    void add_line(Point a, Point b);

    const std::vector<Edge>& edges() const { return edges_; }
    int width() const { return w_; }
    int height() const { return h_; }

  private:
    void push(double x0, double y0, double x1, double y1, float dir);

    std::vector<Edge> edges_;
    int w_ = 0, h_ = 0;
};

} // namespace casteljau
