// feDiffuseLighting and feSpecularLighting (Filter Effects 1, "Filter
// primitive feDiffuseLighting" and "feSpecularLighting", and "Light source
// elements and properties").
#pragma once

#include "casteljau/filter/filter_image.h"

#include <optional>
#include <variant>

namespace casteljau {

/// feDistantLight: angles in degrees.
struct DistantLight {
    double azimuth = 0, elevation = 0;
};

/// fePointLight: position in device px (z in px above the surface plane).
struct PointLight {
    double x = 0, y = 0, z = 0;
};

/// feSpotLight: position and target in device px; the cone's half-angle in
/// degrees, no cone when absent.
struct SpotLight {
    double x = 0, y = 0, z = 0, at_x = 0, at_y = 0, at_z = 0, specular_exponent = 1;
    std::optional<double> cone_angle;
};

using LightSource = std::variant<DistantLight, PointLight, SpotLight>;

/// The attributes of a lighting primitive.
struct Lighting {
    double surface_scale = 1;
    double constant = 1;          ///< kd (diffuse) or ks (specular)
    double specular_exponent = 1; ///< specular only
    bool specular = false;        ///< feSpecularLighting, else feDiffuseLighting
    Premul color;                 ///< lighting-color: straight RGB in the operating space; a unused
    LightSource light;
};

/// Lights the surface z = surface_scale * alpha of `in` into `out` over
/// `sub`: surface normals from the spec's Sobel kernels, with their edge and
/// corner variants at the window's edges; each pixel at its device
/// coordinates (its top-left corner). Precondition: `out` has `in`'s box and
/// is transparent black.
void lighting(const FilterImage& in, FilterImage& out, const Subregion& sub,
              const Lighting& l) noexcept;

} // namespace casteljau
