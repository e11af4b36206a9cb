// Linear and radial gradients (SVG 1.1, chapter 13) and their evaluation.
//
// A gradient lives in its own space, mapped to user space by
// gradientTransform (and, for objectBoundingBox units, by the box: the unit
// square onto the shape's bounding box). For a point g of gradient space the
// parameter t is
//   linear: the projection of g onto p1 -> p2, t = (g - p1).(p2 - p1) / |p2 - p1|^2
//   radial: the t for which g lies on the circle interpolated between the
//           start circle (centre f, the focal point, radius r0 = fr; t = 0)
//           and the end circle (centre c, radius r; t = 1):
//           |g - f - t (c - f)| = r0 + t (r - r0), the larger root of
//           (e.e - dr^2) t^2 - 2 (d.e + r0 dr) t + d.d - r0^2 = 0 with
//           d = g - f, e = c - f, dr = r - r0, where the circle's radius is
//           >= 0 (SVG 2, 14.3.4). With the start circle strictly inside the
//           end circle (|e| < dr, so a = e.e - dr^2 < 0) every point lies on
//           exactly one of those circles:
//           t = (b - sqrt(b^2 - a (d.d - r0^2))) / a, b = d.e + r0 dr.
// then spread (13.2.4): pad clamps t to [0, 1], repeat takes t - floor(t),
// reflect folds t with period 2. A start circle inside the end circle but
// within a thousandth of its edge is moved that far inside, where the root
// above stays well conditioned. A start circle larger than the end circle
// holds it instead: the same circles, run from the other end.
//
// Cones (SVG 2's notes on radial gradients, pservers.html#RadialGradientNotes;
// what browsers draw, as canvas's createRadialGradient does): where neither
// circle holds the other (a focal point outside the end circle, say), the
// circles' family sweeps a cone. A point gets the largest t whose circle
// passes through it with a radius >= 0: the larger root of the quadratic
// above if its radius is not negative, else the smaller one's; where neither
// (no real root, or both radii negative), the point is outside the cone and
// stays transparent. With a = 0 (the start circle touching the end circle
// from inside) the equation is linear. SVG 1.1 moved such a focal point onto
// the circle instead (13.2.3).
//
// Colors between stops are interpolated unpremultiplied (SVG 2, 13.2.4's stop
// colors; browsers, librsvg and resvg interpolate straight colors) in
// sRGB-encoded space, or optionally in linear light, through a lookup table of
// kGradientLut entries: 1/1024 of the gradient's length is below what 8-bit
// output can resolve.
#pragma once

#include "casteljau/geom/affine.h"
#include "casteljau/paint/color.h"
#include "casteljau/paint/pixel8.h"

#include <array>
#include <vector>

namespace casteljau {

enum class Spread { Pad, Reflect, Repeat };

/// A color at an offset along a gradient.
struct GradientStop {
    float offset = 0; ///< in [0, 1], nondecreasing along the list
    Rgba color;       ///< alpha includes stop-opacity
    /// Exact equality of every member.
    constexpr bool operator==(const GradientStop&) const = default;
};

/// A linear or radial gradient as SVG defines it (13.2).
struct Gradient {
    /// Linear (p1 to p2) or radial (centre, radius, focal point).
    enum class Kind { Linear, Radial } kind = Kind::Linear;
    Point p1{0, 0}, p2{1, 0};                ///< linear
    Point center{0.5, 0.5}, focal{0.5, 0.5}; ///< radial
    double radius = 0.5;                     ///< radial
    double focal_radius = 0;                 ///< radial: fr, the start circle's
    Affine transform;                        ///< gradientTransform
    bool object_bounding_box = true;         ///< gradientUnits
    Spread spread = Spread::Pad;
    bool linear_light = false; ///< interpolate in linear light instead of sRGB
    std::vector<GradientStop> stops;
};

inline constexpr int kGradientLut = 1024;

/// A gradient ready to shade device pixels: the device -> gradient-space map,
/// the geometry, and the color table.
class GradientShader {
  public:
    /// A radial gradient's circles as drawn (top of the file): clamped, and
    /// swapped where the start circle is the larger one (t = t0 + t1 t').
    struct RadialForm {
        Point focal, center;   ///< the start and the end circle's centres
        double r0 = 0, dr = 0; ///< the start circle's radius, and r - r0
        double t0 = 0, t1 = 1; ///< (1, -1) when swapped
        bool cone = false;     ///< neither circle holds the other (top of the file)
        double unit = 1;       ///< a cone's: 1 / the circles' size, its units' scale
    };
    /// The circles of radial gradient g as drawn.
    static RadialForm radial_form(const Gradient& g);
    /// `to_device` maps gradient space to device pixels (user transform,
    /// bounding box and gradientTransform composed). False when that map is
    /// singular or the gradient has no stops: then nothing is painted.
    /// `linear_light` asks for linear-light interpolation whatever the gradient says.
    bool prepare(const Gradient& g, const Affine& to_device, float opacity,
                 bool linear_light = false);
    /// The premultiplied color at the centre of device pixel (x, y).
    Premul at(int x, int y) const;
    /// at(x + i, y) into out[i] for i in [0, n): the same values, a row at a time.
    void shade(int x, int y, int n, Premul* out) const;
    /// Where every color of the table is opaque (the stops' and the opacity's
    /// alphas all 1): writes into out the bytes source-over of pixels
    /// [x, x + n) of row y at coverage 1 gives on an 8-bit canvas, whatever
    /// was there (round(255 S + 0 D): the table quantized), and returns
    /// true; else writes nothing and returns false (ShadedSpanPainter).
    bool store_opaque(int x, int y, int n, Premul8* out) const;
    /// The gradient parameter after spread, in [0, 1], at device point p;
    /// NaN outside a radial gradient's cone (top of the file).
    double parameter(Point p) const;

  private:
    /// t of a linear gradient as a function of device coordinates.
    struct LinearForm {
        double x = 0, y = 0, t0 = 0; ///< t = x X + y Y + t0
    };
    void build_table(const Gradient& g, float opacity, bool linear_light);
    // Shading into colors from a table of them: lut_ into Premul, lut8_
    // into Premul8.
    template <Spread S, class P>
    void shade_linear(int x, int y, int n, const P* lut, P* out) const;
    template <Spread S, bool Ring, class P>
    void shade_radial(int x, int y, int n, const P* lut, P* out) const;
    template <Spread S, class P>
    void shade_cone(int x, int y, int n, const P* lut, P* out) const;
    template <Spread S, class P>
    void shade_spread(int x, int y, int n, const P* lut, P* out) const;
    template <class P>
    void shade_from(int x, int y, int n, const P* lut, P* out) const;

    const Gradient* g_ = nullptr;
    /// What the table was built from: compared by value, so a table is never
    /// reused for a different gradient, whatever the gradients' lifetimes.
    std::vector<GradientStop> lut_stops_;
    float lut_opacity_ = -1;
    bool lut_linear_ = false;
    Affine inverse_;
    LinearForm linear_;
    RadialForm radial_;
    std::array<Premul, kGradientLut> lut_{};
    /// lut_ quantized where every entry is opaque (lut_opaque_), for store_opaque.
    std::array<Premul8, kGradientLut> lut8_{};
    bool lut_opaque_ = false;
};

} // namespace casteljau
