// Geometric checks for tests: convex hulls and point comparisons with a
// tolerance scaled to the data.
#pragma once

#include "casteljau/geom/point.h"
#include "casteljau/geom/point3.h"
#include "casteljau/geom/rect.h"

#include <ostream>
#include <span>
#include <vector>

namespace casteljau {
// gtest prints points as coordinates instead of bytes.
inline void PrintTo(const Point& p, std::ostream* os) { *os << "(" << p.x << ", " << p.y << ")"; }
inline std::ostream& operator<<(std::ostream& os, const Point3& p) {
    return os << "(" << p.x << ", " << p.y << ", " << p.z << ")";
}
inline void PrintTo(const Point3& p, std::ostream* os) { *os << p; }
inline void PrintTo(const Vec3& v, std::ostream* os) { *os << Point3{} + v; }
inline void PrintTo(const Rect& r, std::ostream* os) {
    *os << "[" << r.x0 << ", " << r.y0 << " .. " << r.x1 << ", " << r.y1 << "]";
}
} // namespace casteljau

namespace casteljau::testing {

// Convex hull, counter-clockwise (Andrew's monotone chain).
std::vector<Point> convex_hull(std::vector<Point> pts);
// Distance by which p lies outside the convex polygon (0 inside or on it).
double distance_outside(std::span<const Point> hull, Point p);

} // namespace casteljau::testing
