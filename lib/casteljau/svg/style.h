// Presentation properties, their parsing and their inheritance (SVG 1.1,
// 6.4 and the property index, appendix N).
//
// Each element starts from its parent's computed values for the inherited
// properties (fill, fill-opacity, fill-rule, stroke and its relatives, color,
// font-size, visibility) and from the initial values for the others (opacity,
// display). Presentation attributes are applied first, then the declarations
// of the `style` attribute, which take precedence (6.4). `inherit` takes the
// parent's value. Unknown properties are ignored. An invalid value of a known
// property is ignored too (CSS Syntax 3, "parse errors": the declaration is
// dropped, so the property keeps its inherited or initial value); the caller
// is told what was wrong, to warn (or, strict, to stop).
//
// Lengths (CSS Values and Units 3, 5 and 6): px, and the absolute units at
// 96 px per inch (in, cm, mm, Q, pt, pc); em against the element's font-size
// (the parent's, for font-size itself), rem against the root's; ex and ch are
// half an em, the fallback CSS gives when font metrics are not at hand (this
// reader has no fonts); % against what each property names; vw, vh, vmin and
// vmax against the nearest viewport in user units, as percentages are (so
// they scale with the viewBox, as in resvg).
#pragma once

#include "casteljau/paint/color.h"
#include "casteljau/raster/sweep.h"
#include "casteljau/scene/scene.h"
#include "casteljau/svg/basic_shape.h"
#include "casteljau/svg/custom_properties.h"
#include "casteljau/svg/text_properties.h"
#include "casteljau/svg/transform_list.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

/// A fill or stroke paint as specified: none, a color, currentColor,
/// context-fill, context-stroke or a url.
struct PaintSpec {
    /// No paint, a color, currentColor, or the context element's fill or
    /// stroke (SVG 2, 13.3: the shape a marker is on, the use that instances).
    enum class Kind { None, Color, CurrentColor, ContextFill, ContextStroke } kind = Kind::None;
    Rgba color;
    bool from_url = false; ///< url(\#id), with `color`/`kind` as its fallback
    std::string url;       ///< the id after '#', when from_url
};

/// What relative lengths are relative to.
struct LengthContext {
    double font_size = 16;      ///< px: em, and ex and ch as half of it
    double root_font_size = 16; ///< px: rem
    double viewport_w = 100;    ///< user units: vw, vmin, vmax
    double viewport_h = 100;    ///< user units: vh, vmin, vmax
    /// The viewport's normalised diagonal sqrt((w^2 + h^2) / 2): what a
    /// percentage of a length that is neither horizontal nor vertical (a
    /// radius, a stroke width) refers to (SVG 1.1, 7.10).
    double diagonal() const;
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
    double font_size = 16; ///< computed, px (CSS's initial "medium")
    /// marker-start, marker-mid, marker-end: the id of a marker element, or "" for
    /// none (the `marker` shorthand sets all three).
    std::string marker_start, marker_mid, marker_end;
    /// paint-order (SVG 2, 13.5): the order of fill, stroke and markers,
    /// as the positions of each in it (0 first); normal is 0, 1, 2.
    std::array<int, 3> paint_order{0, 1, 2};
    /// shape-rendering: false for crispEdges and optimizeSpeed (no antialiasing).
    bool antialias = true;
    bool visible = true;
    FillRule clip_rule = FillRule::NonZero;
    /// color-interpolation: linearRGB (a mask's luminance is then taken in linear light).
    bool linear_rgb = false;
    /// color-interpolation-filters: linearRGB (initial), else sRGB (auto too).
    bool filters_linear = true;
    /// image-rendering: false for optimizeSpeed, pixelated and crisp-edges
    /// (an image's nearest pixel, not a bilinear blend).
    bool smooth_images = true;
    TextState text; ///< the inherited text properties (svg/text_properties.h)
    /// Custom properties (svg/custom_properties.h), inherited; shared
    /// between the elements that declare none of their own.
    std::shared_ptr<const CustomProperties> custom;
    /// The element's own values of the properties that are not inherited
    /// but that its children may ask for with `inherit` (keep_own_values):
    /// the text ones, and overflow (a marker's overflow="inherit").
    TextProps own_text;
    std::optional<bool> own_overflow;
};

/// transform-box's boxes for SVG elements (CSS Transforms 1, 6.1):
/// content-box is the fill box and border-box the stroke box there.
enum class TransformBox { ViewBox, FillBox, StrokeBox };

/// Not inherited: reset for every element.
struct ElementProps {
    float opacity = 1;
    bool display_none = false;
    /// transform (CSS Transforms 1, 7; SVG 2, 8.5): the attribute or the
    /// CSS property, whichever the cascade takes; nullopt for none.
    std::optional<TransformSteps> transform;
    /// transform-origin (CSS Transforms 1, 6): the point the transform is
    /// applied about, its percentages and keywords of the reference box;
    /// nullopt for the initial value (0 0 in SVG, 50% 50% on the root).
    std::optional<BoxPoint> transform_origin;
    /// transform-box (CSS Transforms 1, 6.1): the reference box of
    /// transform-origin and of translate()'s percentages.
    TransformBox transform_box = TransformBox::ViewBox;
    /// vector-effect: non-scaling-stroke (the other SVG 2 values are valid
    /// and, as in browsers, do nothing).
    bool non_scaling_stroke = false;
    std::string clip_path; ///< the id of a clipPath, "" for none
    /// clip-path as a basic shape or a geometry box (svg/basic_shape.h).
    std::optional<BasicShape> clip_shape;
    std::string mask; ///< the id of a mask, "" for none
    BlendMode blend = BlendMode::Normal;
    bool isolate = false;    ///< isolation: isolate
    bool mask_alpha = false; ///< mask-type: alpha (on a mask element)
    /// overflow: whether a viewport's content shows outside it. Initially
    /// visible, but hidden on the elements that establish a viewport (svg,
    /// symbol, marker, pattern, image) by the UA style sheet (SVG 2, appendix D).
    std::optional<bool> overflow_visible;
    /// clip (CSS 2.1, 11.1.2; SVG 1.1, 14.3.2): on an element that
    /// establishes a viewport, the rectangle its content is clipped to where
    /// overflow hides it, as top, right, bottom, left offsets from the
    /// viewport's top-left corner; nullopt for an edge of the viewport (auto).
    std::array<std::optional<double>, 4> clip_rect;
    /// filter (Filter Effects 1, 11): the value as written, checked by
    /// parse_filter_list (svg/filter_functions.h); "" for none.
    std::string filter;
    /// flood-color and flood-opacity (15.14), lighting-color (15.16): on
    /// filter primitives, not inherited; a color that is currentColor is
    /// nullopt (the reader takes the element's color).
    std::optional<Rgba> flood_color = Rgba{0, 0, 0, 1};
    float flood_opacity = 1;
    std::optional<Rgba> lighting_color = Rgba{1, 1, 1, 1};
    TextProps text; ///< the text properties that are not inherited
};

/// Keeps the computed values of element `name` that `inherit` takes in its
/// children (StyleState::own_text, own_overflow), once its declarations are
/// applied. Overflow not declared is visible, but hidden on the elements
/// that establish a viewport (ElementProps::overflow_visible).
inline void keep_own_values(StyleState& s, const ElementProps& props, std::string_view name) {
    s.own_text = props.text;
    const bool viewport = name == "svg" || name == "symbol" || name == "marker" ||
                          name == "pattern" || name == "image";
    s.own_overflow = props.overflow_visible.value_or(!viewport);
}

/// Applies one property. Returns "" when applied or unknown, otherwise what is
/// wrong with the value (which is then ignored). `ctx` is the element's
/// (its font_size already computed, see font-size's own rule above).
std::string apply_property(std::string_view name, std::string_view value, const StyleState& parent,
                           StyleState& style, ElementProps& props, const LengthContext& ctx);

/// A number (CSS's <number>, with an optional leading '+'): nullopt when
/// malformed or not finite. With `rest`, what follows the number goes there
/// (a unit, say); without, anything but whitespace after it is an error.
std::optional<double> parse_number(std::string_view text, std::string_view* rest = nullptr);

/// A length: a number with an optional unit (see above; % of `percent_of`);
/// nullopt when malformed, not finite, or in an unknown unit.
std::optional<double> parse_length(std::string_view text, double percent_of = 0,
                                   const LengthContext& ctx = {});

/// transform-origin (CSS Transforms 1, 6): one to three values, each a length,
/// a percentage of the reference box or a keyword; the third (z) is ignored
/// in 2D. nullopt when invalid.
std::optional<BoxPoint> parse_transform_origin(std::string_view v, const LengthContext& ctx);

/// A font-size: a keyword (xx-small to xxx-large, larger, smaller) or a
/// non-negative length, em and % of `parent` (the parent's font size);
/// nullopt when invalid. Shared with the font shorthand.
std::optional<double> parse_font_size(std::string_view v, double parent, const LengthContext& ctx);

/// Resolves a paint to a color; nullopt for none.
std::optional<Rgba> resolve_paint(const PaintSpec& p, const StyleState& s);

} // namespace casteljau
