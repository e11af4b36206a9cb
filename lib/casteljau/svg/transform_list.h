// Transform lists, in the two syntaxes SVG files carry them:
//
// - The transform attribute (SVG 1.1, 7.6; SVG 2, 8.5): matrix(a b c d e f),
//   translate(x [y]), scale(sx [sy]), rotate(deg [cx cy]), skewX(deg),
//   skewY(deg), arguments and functions separated by whitespace and/or
//   commas, plain numbers in user units and degrees. SVG 2 makes the
//   attribute the presentation attribute of the CSS transform property, so
//   browsers also take CSS's units (translate(5px, 1em), rotate(0.25turn),
//   translate(50%)) and its function names (translateX, scaleY, skew) there;
//   so does this parser.
// - The CSS transform property (CSS Transforms 1, 7), in a style sheet or a
//   style attribute: `none` or functions separated by whitespace, arguments
//   separated by one comma each, lengths with a unit (or 0), angles with
//   deg, rad, grad or turn (or 0); names ASCII case-insensitive.
//
// Functions apply left to right as nested coordinate systems (the product in
// list order). A translation's percentages refer to the transform's
// reference box (transform-box), known only where the element is drawn, so
// a list parses to steps that keep them apart (TransformSteps::at).
#pragma once

#include "casteljau/geom/affine.h"

#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

struct LengthContext;

/// A parsed transform list: each step a matrix, and for translations by a
/// percentage the fraction of the reference box's width and height added
/// to its offset.
struct TransformSteps {
    /// One function of the list.
    struct Step {
        Affine m;          ///< the function's matrix, percentages aside
        Vec2 box_fraction; ///< (0, 0) but for a translation by a percentage
    };
    std::vector<Step> steps; ///< empty: none (the identity)
    /// The transform with percentages of a reference box of size w x h.
    Affine at(double w, double h) const;
    /// Whether any step refers to the reference box.
    bool needs_box() const;
};

/// Which syntax (top of the file).
enum class TransformSyntax { Attribute, Css };

/// The steps, or an error message naming the offending function.
struct TransformParse {
    TransformSteps value;
    std::string error; ///< empty on success
};

/// Parses a transform list in `syntax`; lengths in em, vw and the like take
/// `ctx`.
TransformParse parse_transform(std::string_view text, TransformSyntax syntax,
                               const LengthContext& ctx);

/// The transform, or an error message naming the offending function.
struct TransformResult {
    Affine transform;
    std::string error; ///< empty on success
};

/// A transform attribute with no reference box (gradientTransform,
/// patternTransform): a percentage is an error.
TransformResult parse_transform_list(std::string_view text);

/// A point given as lengths plus fractions of a reference box
/// (transform-origin): at(box) = box's corner + px + fraction * box's size.
struct BoxPoint {
    Vec2 px;
    Vec2 fraction;
    /// The point in a reference box at (x, y) of size w x h.
    Point at(double x, double y, double w, double h) const {
        return {x + px.x + fraction.x * w, y + px.y + fraction.y * h};
    }
};

} // namespace casteljau
