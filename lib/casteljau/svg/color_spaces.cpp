#include "casteljau/svg/color_spaces.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace casteljau {

namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

Vec3 times(const Mat3& m, const Vec3& v) {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
            m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

// Linear sRGB to the encoded value (IEC 61966-2-1), clipped to [0, 1].
float encode(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return float(c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055);
}

Rgba from_linear(const Vec3& rgb, float alpha) {
    return {encode(rgb[0]), encode(rgb[1]), encode(rgb[2]), alpha};
}

// XYZ (D65) to linear sRGB.
constexpr Mat3 kXyzToSrgb = {{{3.2409699419045226, -1.537383177570094, -0.4986107602930034},
                              {-0.9692436362808796, 1.8759675015077202, 0.04155505740717559},
                              {0.05563007969699366, -0.20397695888897652, 1.0569715142428786}}};
// Bradford chromatic adaptation, D50 to D65.
constexpr Mat3 kD50ToD65 = {{{0.955473421488075, -0.02309845494876471, 0.06325924320057072},
                             {-0.0283697093338637, 1.0099953980813041, 0.021041441191917323},
                             {0.012314014864481998, -0.020507649298898964, 1.330365926242124}}};
// OKLab to LMS (cube roots), and LMS to linear sRGB.
constexpr Mat3 kOklabToLms = {{{1.0, 0.3963377773761749, 0.2158037573099136},
                               {1.0, -0.1055613458156586, -0.0638541728258133},
                               {1.0, -0.0894841775298119, -1.2914855480194092}}};
constexpr Mat3 kLmsToSrgb = {{{4.0767416621, -3.3077115913, 0.2309699292},
                              {-1.2684380046, 2.6097574011, -0.3413193965},
                              {-0.0041960863, -0.7034186147, 1.7076147010}}};

} // namespace

Rgba lab_to_srgb(double l, double a, double b, float alpha) {
    constexpr double kappa = 24389.0 / 27, epsilon = 216.0 / 24389;
    // D50's white point, from its chromaticity (0.3457, 0.3585).
    constexpr Vec3 white = {0.3457 / 0.3585, 1.0, (1.0 - 0.3457 - 0.3585) / 0.3585};
    const double fy = (l + 16) / 116, fx = fy + a / 500, fz = fy - b / 200;
    const double x = fx * fx * fx > epsilon ? fx * fx * fx : (116 * fx - 16) / kappa;
    const double y = l > kappa * epsilon ? fy * fy * fy : l / kappa;
    const double z = fz * fz * fz > epsilon ? fz * fz * fz : (116 * fz - 16) / kappa;
    const Vec3 d50 = {x * white[0], y * white[1], z * white[2]};
    return from_linear(times(kXyzToSrgb, times(kD50ToD65, d50)), alpha);
}

Rgba oklab_to_srgb(double l, double a, double b, float alpha) {
    Vec3 lms = times(kOklabToLms, {l, a, b});
    for (double& c : lms) c = c * c * c;
    return from_linear(times(kLmsToSrgb, lms), alpha);
}

} // namespace casteljau
