// feGaussianBlur (Filter Effects 1, 15.15) and the CSS blur() function.
#pragma once

#include "casteljau/filter/filter_image.h"

namespace casteljau {

/// The blur of `in` with standard deviations sx, sy (device px, >= 0; 0
/// leaves that direction unblurred) into `out` over `sub`, on premultiplied
/// channels. Reads beyond the window as `edge` says. With `alpha_only`, the
/// alpha alone is blurred (a quarter of the work) and the colors are 0: for
/// inputs with no color (SourceAlpha, a shadow's mask).
void gaussian_blur(const FilterImage& in, FilterImage& out, const Subregion& sub, double sx,
                   double sy, EdgeMode edge, bool alpha_only = false);

/// How far (device px, each side) a blur of standard deviation s reaches:
/// no output pixel depends on input farther away.
int blur_reach(double s);

/// The largest standard deviation blurred (device px); larger ones are
/// clamped to it. Beyond it a blur spreads a layer's content thinner than
/// an 8-bit step over a frame of 16384 px.
inline constexpr double kMaxBlurSigma = 2048;

} // namespace casteljau
