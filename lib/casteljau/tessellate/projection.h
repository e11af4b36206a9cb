// ScreenProjection: where a point of space lands on the image, in pixels.
//
// A pinhole camera: camera coordinates c = (x, y, z) = (right, down, forward)
// . (p - eye), and the pixel is centre + focal (x / z, y / z). `near` is the
// smallest depth drawn; everything closer is clipped by the rasterizer. The
// adaptive tessellator measures flatness through this mapping, so its
// tolerance is in the same device pixels as the 2D flattener's.
#pragma once

#include "casteljau/geom/point.h"
#include "casteljau/geom/point3.h"

namespace casteljau {

/// A pinhole projection from world space to pixels.
struct ScreenProjection {
    Point3 eye;
    Vec3 right{1, 0, 0}, down{0, 1, 0}, forward{0, 0, 1}; ///< orthonormal
    double focal = 1;                                     ///< pixels at depth 1
    Point center;                                         ///< principal point, pixels
    double near = 1e-3;
    int width = 1, height = 1; ///< the image, pixels

    /// World to camera space (x right, y down, z forward).
    constexpr Vec3 to_camera(Point3 p) const {
        const Vec3 d = p - eye;
        return {d.dot(right), d.dot(down), d.dot(forward)};
    }
    /// Camera space to pixels (perspective divide by z).
    constexpr Point to_pixels(Vec3 c) const {
        return {center.x + focal * c.x / c.z, center.y + focal * c.y / c.z};
    }
    /// World space to pixels.
    constexpr Point project(Point3 p) const { return to_pixels(to_camera(p)); }
};

} // namespace casteljau
