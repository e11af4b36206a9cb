// Cameras: look-at, perspective, and an orbit view fitted to a scene.
//
// World space is z-up (as the Utah teapot and Quake maps are). A view at
// azimuth AZ and elevation EL (degrees) looks at the centre of the scene's
// bounds from the direction (cos EL cos AZ, cos EL sin AZ, sin EL), from just
// far enough that the bounding sphere fills the narrower side of the image
// with a 5% margin. The control hull bounds the surface, so its box does too.
#pragma once

#include "casteljau/geom/point3.h"
#include "casteljau/tessellate/projection.h"

namespace casteljau {

/// A camera looking from `eye` at `target`, with `up` upwards and a vertical field of view.
struct LookAt {
    Point3 eye{0, -10, 0}, target{};
    Vec3 up{0, 0, 1};
    double fov_deg = 35; ///< vertical field of view
};

/// The projection of a look-at camera onto a width x height image. Requires eye
/// != target, up not parallel to the line of sight, 0 < fov_deg < 180.
ScreenProjection make_projection(const LookAt& camera, int width, int height);

LookAt orbit_view(const Box3& bounds, double azimuth_deg, double elevation_deg, int width,
                  int height, double fov_deg = 35);

} // namespace casteljau
