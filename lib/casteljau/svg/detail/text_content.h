// Internal to the SVG reader (not installed): a <text> element's content
// once read (svg/text.cpp) and before it is laid out (svg/text_layout.cpp).
//
// Its characters are the "addressable characters" of SVG 2, 11.8.3: after
// white space is processed, each with the span (text, tspan, textPath, tref
// or a) it belongs to and the x, y, dx, dy and rotate values that apply to
// it from the nearest element that gives one for its index.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/svg/style.h"
#include "casteljau/text/layout.h"

#include <optional>
#include <pugixml.hpp>
#include <vector>

namespace casteljau::svg_detail {

struct TextSpan {
    pugi::xml_node node; ///< the element, for its paints and messages
    StyleState style;
    TextProps props;
    /// Its baseline's shift from the text's, px, up: the sum of its own
    /// baseline-shift and its ancestors'.
    double baseline_shift = 0;
    /// The spans whose text-decoration it is drawn with, outermost first.
    std::vector<std::uint32_t> decorations;
    int text_path = -1;       ///< index into TextContent::paths, or -1
    std::uint32_t parent = 0; ///< the span of the parent element (the text's own: itself)
};

struct TextPathRef {
    Path path; ///< in the text's user space
    double start_offset = 0;
    bool start_percent = false; ///< start_offset is a fraction of the length
    /// The path's pathLength: a start_offset in its units (svg/path_length.cpp).
    std::optional<double> path_length;
    bool right_side = false; ///< side="right": along the path's reverse
};

struct TextChar {
    char32_t c = 0;
    std::uint32_t span = 0;
    std::optional<double> x, y;
    double dx = 0, dy = 0;
    std::optional<double> rotate; ///< degrees
};

/// textLength on an element: its characters [begin, end) take `length`.
struct TextLengthSpec {
    std::size_t begin = 0, end = 0;
    double length = 0;
    bool glyphs = false; ///< lengthAdjust="spacingAndGlyphs": glyphs stretch too
};

struct TextContent {
    std::vector<TextSpan> spans;
    std::vector<TextChar> chars;
    std::vector<TextPathRef> paths;
    std::vector<TextLengthSpec> lengths;
};

/// One laid glyph: the glyph, and the map from its own pixel space (origin on
/// its baseline, y down) to the text's user space.
struct PlacedGlyph {
    LaidGlyph glyph;
    Affine transform;
};

/// One cluster's share of a decoration line: the rectangle [0, width] x
/// [y - thickness / 2, y + thickness / 2] of the cluster's decoration space,
/// mapped by `transform` to user space.
struct DecorationPiece {
    std::uint32_t owner = 0; ///< the span that set the decoration
    int line = 0;            ///< 0 underline, 1 overline, 2 line-through
    double width = 0, y = 0, thickness = 0;
    Affine transform;
};

struct TextLayout {
    std::vector<PlacedGlyph> glyphs;
    std::vector<DecorationPiece> decorations;
};

/// Lays out the content (svg/text_layout.cpp).
TextLayout layout_text(FontDatabase& fonts, const TextContent& content);

/// The shaping style of a span.
TextStyle text_style(const StyleState& s);

} // namespace casteljau::svg_detail
