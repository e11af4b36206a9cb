#include "casteljau/render3d/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace casteljau {

namespace {

double radians(double deg) { return deg * std::numbers::pi / 180.0; }

} // namespace

ScreenProjection make_projection(const LookAt& camera, int width, int height) {
    ScreenProjection s;
    s.eye = camera.eye;
    s.forward = (camera.target - camera.eye).normalized();
    s.right = s.forward.cross(camera.up).normalized();
    s.down = s.forward.cross(s.right);
    s.focal = 0.5 * height / std::tan(0.5 * radians(camera.fov_deg));
    s.center = {0.5 * width, 0.5 * height};
    s.width = width;
    s.height = height;
    // 1e-3 of the distance to the target: close enough never to cut what the
    // camera was aimed at, far enough to keep depth resolution in floats.
    s.near = 1e-3 * (camera.target - camera.eye).length();
    return s;
}

LookAt orbit_view(const Box3& bounds, double azimuth_deg, double elevation_deg, int width,
                  int height, double fov_deg) {
    LookAt c;
    c.fov_deg = fov_deg;
    c.target = bounds.empty() ? Point3{} : bounds.center();
    const double radius = std::max(0.5 * bounds.diagonal(), 1e-9);
    const double az = radians(azimuth_deg), el = radians(elevation_deg);
    const Vec3 dir{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
    // The narrower of the vertical and horizontal fields of view.
    const double half_v = 0.5 * radians(fov_deg);
    const double half_h = std::atan(std::tan(half_v) * width / height);
    const double distance = 1.05 * radius / std::sin(std::min(half_v, half_h));
    c.eye = c.target + distance * dir;
    // Straight down or up the z axis, "up" on the image is +y instead.
    c.up = std::abs(dir.z) > 0.999 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
    return c;
}

} // namespace casteljau
