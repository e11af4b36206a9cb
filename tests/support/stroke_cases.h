// Stroke test helpers: a stroke geometry, path data, and the coverage of
// outline polygons through the rasterizer.
#pragma once

#include "casteljau/curve/path_data.h"
#include "casteljau/raster/edge.h"
#include "casteljau/raster/rasterizer.h"
#include "casteljau/scene/scene.h"
#include "casteljau/stroke/stroker.h"
#include "coverage.h"

#include <vector>

namespace casteljau::testing {

inline StrokeGeometry style(double width, LineCap cap = LineCap::Butt,
                            LineJoin join = LineJoin::Miter) {
    StrokeGeometry s;
    s.width = width;
    s.cap = cap;
    s.join = join;
    return s;
}

inline Path parse(const char* d) { return parse_path_data(d).path; }

// The signed area of a polygon (the shoelace formula).
inline double area(const Polygon& p) { // signed, shoelace
    double a = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        a += p[i].to_vec().cross(p[(i + 1) % p.size()].to_vec());
    return a / 2;
}

// The coverage of outline polygons (nonzero) on a w x h image.
inline CoverageImage cover(const std::vector<Polygon>& polys, int w, int h) {
    EdgeList edges;
    edges.reset(w, h);
    for (const Polygon& p : polys)
        for (std::size_t i = 0; i < p.size(); ++i) edges.add_line(p[i], p[(i + 1) % p.size()]);
    CoverageImage img(w, h);
    Rasterizer().fill(edges, FillRule::NonZero, true, img);
    return img;
}

} // namespace casteljau::testing
