// CSS/SVG color values: the 147 SVG 1.1 color keywords (section 4.4),
// #rgb, #rrggbb, rgb(r, g, b) with integers or percentages (clamped to range,
// as CSS 2 says), and `transparent`. Keywords are case-insensitive.
#pragma once

#include "casteljau/paint/color.h"

#include <optional>
#include <string_view>

namespace casteljau {

std::optional<Rgba> parse_color(std::string_view text);

} // namespace casteljau
