// Viewports: the viewBox and preserveAspectRatio attributes and the mapping
// they define from a view box onto a viewport (SVG 1.1, 7.7 and 7.8).
//
// The mapping scales the box by sx = width / box.w, sy = height / box.h, or
// with an alignment by s = min(sx, sy) (meet) or max(sx, sy) (slice) in both
// directions, and moves the scaled box so that its min, mid or max edge lies
// on the viewport's; "none" scales non-uniformly.
//
// Parsing follows the spec's error handling: a viewBox that is not four
// numbers, or whose width or height is negative, is in error and ignored
// (the element is then drawn as if it had none); a zero width or height
// disables rendering of the element; an invalid preserveAspectRatio takes
// the initial value, xMidYMid meet.
#pragma once

#include "casteljau/geom/affine.h"

#include <optional>
#include <string>
#include <string_view>

namespace casteljau {

/// A view box: the user-space rectangle a viewport shows.
struct ViewBox {
    double x = 0, y = 0, w = 0, h = 0;
};

/// A parsed viewBox attribute: the box, or what is wrong with it.
struct ViewBoxResult {
    std::optional<ViewBox> box; ///< empty when in error (and then ignored)
    std::string error;          ///< non-empty when in error
};

/// Parses "x y w h" (whitespace and/or commas). A box of zero width or height
/// is returned as such: the caller disables rendering.
ViewBoxResult parse_view_box(std::string_view text);

/// preserveAspectRatio: the alignment of each axis and meet or slice.
struct AspectRatio {
    /// Where the box goes on one axis: min, mid or max edge aligned.
    enum class Align { Min, Mid, Max };
    bool none = false; ///< "none": scale each axis on its own
    Align x = Align::Mid, y = Align::Mid;
    bool slice = false; ///< cover the viewport (slice) instead of fitting (meet)
};

/// Parses "[defer] <align> [meet|slice]"; nullopt when invalid.
std::optional<AspectRatio> parse_aspect_ratio(std::string_view text);

/// The transform from the box onto a viewport of the given size at (vx, vy).
Affine view_box_transform(const ViewBox& box, const AspectRatio& ar, double vx, double vy,
                          double width, double height);

} // namespace casteljau
