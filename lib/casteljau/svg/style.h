// Presentation properties, their parsing and their inheritance (SVG 1.1,
// 6.4 and the property index, appendix N).
//
// Each element starts from its parent's computed values for the inherited
// properties (fill, fill-opacity, fill-rule, stroke and its relatives, color,
// visibility) and from the initial values for the others (opacity, display).
// Presentation attributes are applied first, then the declarations of the
// `style` attribute, which take precedence (6.4). `inherit` takes the parent's
// value. Unknown properties are ignored; a malformed value of a known
// property is an error (the reader reports it with the element and line).
#pragma once

#include "casteljau/paint/color.h"
#include "casteljau/raster/sweep.h"
#include "casteljau/scene/scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

/// A fill or stroke paint as specified: none, a color, currentColor or a url.
struct PaintSpec {
    /// No paint, a color, or currentColor.
    enum class Kind { None, Color, CurrentColor } kind = Kind::None;
    Rgba color;
    bool from_url = false; ///< url(\#id), with `color`/`kind` as its fallback
    std::string url;       ///< the id after '#', when from_url
};

/// The computed style properties the cascade carries from parent to child.
struct StyleState {
    PaintSpec fill{PaintSpec::Kind::Color, {0, 0, 0, 1}, false, {}};
    float fill_opacity = 1;
    FillRule fill_rule = FillRule::NonZero;
    PaintSpec stroke;
    float stroke_opacity = 1;
    StrokeGeometry stroke_geometry;
    Rgba color{0, 0, 0, 1};
    bool visible = true;
};

/// Not inherited: reset for every element.
struct ElementProps {
    float opacity = 1;
    bool display_none = false;
};

/// Applies one property. Returns "" when applied or unknown, otherwise what is
/// wrong with the value.
std::string apply_property(std::string_view name, std::string_view value, const StyleState& parent,
                           StyleState& style, ElementProps& props);

/// Splits a `style` attribute into declarations and applies each.
std::string apply_style_attribute(std::string_view css, const StyleState& parent, StyleState& style,
                                  ElementProps& props);

/// A length: a number with an optional unit (px, pt, pc, mm, cm, in, em, ex,
/// or % of `percent_of`); nullopt when malformed or not finite.
std::optional<double> parse_length(std::string_view text, double percent_of = 0);

/// Resolves a paint to a color; nullopt for none.
std::optional<Rgba> resolve_paint(const PaintSpec& p, const StyleState& s);

} // namespace casteljau
