// CSS basic shapes as clip paths (CSS Masking 1, 6.1; CSS Shapes 1, 3.1):
//
//   clip-path: <basic-shape> || <geometry-box>
//   circle( <radius>? [ at <position> ]? )
//   ellipse( [ <radius> <radius> ]? [ at <position> ]? )
//   inset( <length-percentage>{1,4} [ round <border-radius> ]? )
//   polygon( [ <fill-rule> , ]? [ <length-percentage> <length-percentage> ]# )
//   path( [ <fill-rule> , ]? <string> )
//
// with <radius> a non-negative <length-percentage>, closest-side (the
// initial value) or farthest-side. Percentages refer to the reference box:
// x and widths to its width, y and heights to its height, a circle's radius
// to its normalised diagonal sqrt((w^2 + h^2) / 2). A polygon's and a path's
// coordinates are from the box's corner. <position> takes one or two values
// (keywords, lengths, percentages; initially center): the four-value form
// (`right 10px top 5px`) is not read. <border-radius> is one to four
// horizontal radii, optionally `/` and one to four vertical ones, corners in
// the order top-left, top-right, bottom-right, bottom-left, scaled down
// together where two on one side overlap (CSS Backgrounds 3, 5.5).
//
// The reference box (<geometry-box>; SVG elements have no CSS boxes, so
// CSS Masking 1 maps them): fill-box, and content-box and padding-box, the
// element's object bounding box; stroke-box, and border-box and
// margin-box, that box with the stroke; view-box, the nearest viewport.
// Initially border-box. A box alone (`clip-path: fill-box`) clips to it.
// Lengths must have units (0 aside), as in any CSS value.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/geom/rect.h"
#include "casteljau/raster/sweep.h"

#include <array>
#include <optional>
#include <string_view>
#include <vector>

namespace casteljau {

struct LengthContext;

/// A length plus a fraction of one side of the reference box.
struct BoxLength {
    double px = 0;       ///< user units
    double fraction = 0; ///< of the side it refers to
    /// The length for a side of `side` user units.
    double of(double side) const { return px + fraction * side; }
};

/// The reference box of a basic shape (top of the file).
enum class ShapeBox { Fill, Stroke, View };

/// A parsed basic shape; resolved against its reference box by shape_path.
struct BasicShape {
    /// Which function; Box: the reference box alone.
    enum class Kind { Box, Circle, Ellipse, Inset, Polygon, Path } kind = Kind::Box;
    ShapeBox box = ShapeBox::Stroke; ///< the reference box
    /// A circle's or an ellipse's radius: a length, or a side keyword.
    struct Radius {
        /// A length, or the distance to the closest or farthest side.
        enum class Kind { Length, ClosestSide, FarthestSide } kind = Kind::ClosestSide;
        BoxLength length; ///< for Kind::Length
    };
    std::array<Radius, 2> radii;      ///< the circle's (first), or the ellipse's rx and ry
    BoxLength cx{0, 0.5}, cy{0, 0.5}; ///< the centre (circle, ellipse)
    std::array<BoxLength, 4> inset;   ///< top, right, bottom, left
    /// inset's corner radii, horizontal then vertical, top-left first.
    std::array<BoxLength, 4> round_x, round_y;
    std::vector<std::array<BoxLength, 2>> points; ///< the polygon's
    Path path;                                    ///< path()'s, from the box's corner
    FillRule fill_rule = FillRule::NonZero;       ///< polygon's and path()'s
};

/// A clip-path value that is a basic shape, a geometry box or both;
/// nullopt when it is none of these or invalid (url() and none included).
std::optional<BasicShape> parse_basic_shape(std::string_view value, const LengthContext& ctx);

/// The shape's outline in user space, its reference box being `box`.
Path shape_path(const BasicShape& s, const Rect& box);

} // namespace casteljau
