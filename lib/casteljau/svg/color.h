// CSS color values as browsers parse them (CSS Color 4; SVG 1.1, 4.4):
// the 147 named colors and `transparent` (case-insensitive), #rgb, #rgba,
// #rrggbb, #rrggbbaa, rgb()/rgba() and hsl()/hsla() in the legacy comma form
// or the modern space form with "/ alpha", numbers or percentages (out of
// range clamped), hue angles in deg, grad, rad or turn; hwb(), lab(), lch(),
// oklab() and oklch() in the modern form (color_spaces.h; out of the sRGB
// gamut, clipped), `none` as 0 in the modern form; and SVG 1.1's
// "color icc-color(...)" (the sRGB color is used). Not colors here, so
// nullopt: currentColor, inherit and paints (the style cascade resolves
// them), and the deprecated system colors, which resvg and librsvg reject too.
#pragma once

#include "casteljau/paint/color.h"

#include <optional>
#include <string_view>

namespace casteljau {

std::optional<Rgba> parse_color(std::string_view text);

} // namespace casteljau
