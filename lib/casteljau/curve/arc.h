// SVG elliptical arcs (SVG 1.1 Second Edition, appendix F.6).
//
// An arc command gives end points, radii rx ry, an x-axis rotation phi and two
// flags. F.6.5 converts that to the centre parameterisation (centre, start
// angle theta1, sweep dtheta); F.6.6 corrects out-of-range radii: negative
// radii take their absolute value, and if Lambda = x1'^2/rx^2 + y1'^2/ry^2 > 1
// both radii are scaled by sqrt(Lambda) so that exactly one ellipse fits.
// Zero radius means a straight line and coincident end points mean no arc at
// all (F.6.2); `svg_arc` reports those as `kind`.
//
// The arc is then the image of a unit-circle arc under
//   M = translate(centre) * rotate(phi) * scale(rx, ry),
// so it is split into pieces of at most 90 degrees, each an exact conic (the
// circular arc w = cos(a/2), mapped by M: conics are affine invariant) or a
// cubic with the classic handle length k = 4/3 tan(a/4) (radial error below
// 2.8e-4 of the radius for 90 degrees; Riskus 2006).
#pragma once

#include "casteljau/curve/bez.h"
#include "casteljau/curve/conic.h"

#include <array>

namespace casteljau {

/// The endpoint parameterisation of an SVG arc command (SVG 1.1, F.6.2).
struct SvgArcInput {
    Point from, to;
    Vec2 radii;
    double x_rotation_deg = 0;
    bool large_arc = false, sweep = false;
};

/// The centre parameterisation of an SVG arc (F.6.5), or what degenerates it.
struct EllipseArc {
    /// An arc, a straight line (a zero radius), or nothing (equal end points).
    enum class Kind { Arc, Line, Nothing } kind = Kind::Arc;
    Point center;
    Vec2 radii;                    ///< corrected radii, both > 0 for an Arc
    double x_rotation = 0;         ///< radians
    double theta1 = 0, dtheta = 0; ///< radians; dtheta > 0 runs in the positive-angle direction
    /// The map of the unit circle onto the ellipse (scale, rotate, translate).
    Affine unit_circle_map() const;
};

EllipseArc svg_arc(const SvgArcInput& in);

/// At most four pieces of at most 90 degrees each; returns how many. The first
/// piece starts exactly at in.from and the last ends exactly at in.to.
int svg_arc_to_conics(const SvgArcInput& in, std::array<Conic, 4>& out);
int svg_arc_to_cubics(const SvgArcInput& in, std::array<CubicBez, 4>& out);

} // namespace casteljau
