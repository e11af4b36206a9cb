// The CSS Color 4 spaces beyond sRGB that color functions name (lab(),
// lch(), oklab(), oklch()), converted to sRGB for drawing.
//
// CIE Lab (CSS Color 4, 9): D50; to XYZ by the CIE formulas with
// kappa = 24389/27 and epsilon = 216/24389, to D65 by the Bradford matrix,
// to linear sRGB by sRGB's matrix, all as CSS Color 4's sample code (18)
// gives them. OKLab (10; Ottosson 2020): through LMS, cubed, to linear sRGB
// by the matrices of the same section. LCH and OKLCh are their polar forms:
// a = C cos h, b = C sin h. Out of the sRGB gamut, each channel is clipped to
// [0, 1] after the transfer function (what browsers ship; CSS Color 4's
// chroma-reducing gamut mapping, 13.2, is not done).
#pragma once

#include "casteljau/paint/color.h"

namespace casteljau {

/// CIE Lab (L in [0, 100]), D50, to sRGB.
Rgba lab_to_srgb(double l, double a, double b, float alpha);
/// OKLab (L in [0, 1]) to sRGB.
Rgba oklab_to_srgb(double l, double a, double b, float alpha);

} // namespace casteljau
