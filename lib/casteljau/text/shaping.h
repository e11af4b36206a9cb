// Shaping: which glyphs draw a run of text in one font and where they go,
// with HarfBuzz (kerning, ligatures, mark positioning, the complex scripts).
//
// A run is a range of a longer text, so that shaping sees its context
// (Arabic joining across a font change, say). Glyphs come in visual order;
// each names the index in the text of the first character of its cluster
// (the characters it draws, with the glyphs of the same cluster). Advances
// and offsets are in font units, y up.
#pragma once

#include "casteljau/text/font.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

enum class TextDirection { Ltr, Rtl, Ttb };

/// An OpenType feature switched on or off ("liga", "kern", "smcp" ...).
struct FontFeature {
    char tag[4] = {' ', ' ', ' ', ' '};
    bool on = true;
};

/// How to shape a run.
struct ShapeOptions {
    TextDirection direction = TextDirection::Ltr;
    std::string language; ///< BCP 47, "" for the default
    std::vector<FontFeature> features;
};

/// One glyph of a shaped run, in font units (y up).
struct ShapedGlyph {
    std::uint32_t glyph = 0;
    std::uint32_t cluster = 0; ///< index in the text of its cluster's first character
    double x_advance = 0, y_advance = 0;
    double x_offset = 0, y_offset = 0;
};

/// Shapes text[begin, end) in `font`.
std::vector<ShapedGlyph> shape_run(const Font& font, std::u32string_view text, std::size_t begin,
                                   std::size_t end, const ShapeOptions& options);

} // namespace casteljau
