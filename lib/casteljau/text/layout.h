// Text layout: a paragraph of styled text to glyphs placed in pixels.
//
// shape_paragraph does what every text engine does before it places a
// glyph (the pipeline of HarfBuzz's documentation, "what shaping is not"):
//   1. bidi: the embedding level of each character (text/bidi.h);
//   2. itemisation: maximal runs of one level, one style and one font, the
//      font being the style's first match that has the character, else the
//      fallback fontconfig finds for it (CSS Fonts 4, 5.2 "cluster matching":
//      a combining mark stays with the font of its base);
//   3. shaping of each run in the context of the whole text (text/shaping.h);
//   4. the runs in visual order (UAX #9, L2).
// Placing the glyphs is the caller's: SVG positions characters one by one
// (x, y, dx, dy, rotate, textPath); text_to_path sets one line.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/text/font_database.h"
#include "casteljau/text/shaping.h"

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace casteljau {

/// How a range of characters is set.
struct TextStyle {
    FontQuery font;
    double size = 16; ///< px
    /// font-size-adjust (CSS Fonts 4, 2.6): the size is scaled so that each
    /// font's x-height is this fraction of it; none when nullopt.
    std::optional<double> size_adjust;
    std::vector<FontVariation> variations;
    /// OpenType features: kerning off is {"kern", false}, small caps {"smcp"}.
    std::vector<FontFeature> features;
    std::string language;      ///< BCP 47, "" for the default
    double letter_spacing = 0; ///< px after each cluster (CSS Text 3, 8.2)
    double word_spacing = 0;   ///< px after each space (CSS Text 3, 8.1)
};

/// One shaped glyph, in pixels with y down.
struct LaidGlyph {
    std::shared_ptr<const Font> font; ///< null for a character no font draws
    std::uint32_t glyph = 0;
    /// The characters of its cluster: text[begin, end), logical order.
    /// Glyphs of one cluster share them; `first` marks the cluster's first glyph.
    std::size_t begin = 0, end = 0;
    bool first = true;
    std::uint32_t style = 0; ///< index into the styles
    double scale = 0;        ///< px per font unit: size / units per em
    Vec2 advance;            ///< pen advance, px, y down
    Vec2 offset;             ///< from the pen to the glyph's origin, px, y down
    bool rtl = false;
};

/// Shapes `text`, character i set in styles[style_of[i]], glyphs in visual
/// order (left to right; top to bottom for Ttb). `levels`, when given, are
/// the characters' bidi embedding levels (a caller that overrides the bidi
/// algorithm, as unicode-bidi: bidi-override does, computes them);
/// otherwise the algorithm's for the direction's base level.
std::vector<LaidGlyph> shape_paragraph(FontDatabase& fonts, std::u32string_view text,
                                       const std::vector<TextStyle>& styles,
                                       const std::vector<std::uint32_t>& style_of,
                                       TextDirection direction,
                                       const std::vector<std::uint8_t>* levels = nullptr);

/// Appends the outline of `g` to `out`, mapped by `m` from the glyph's own
/// pixel space: its origin on the baseline at (0, 0), y down.
void append_glyph(Path& out, const LaidGlyph& g, const Affine& m);

/// Whether a character is one that word-spacing widens (CSS Text 3, 8.1:
/// the space, the no-break space and the other word separators).
bool is_word_separator(char32_t c);

/// One line of text as a path, for applications: shaped with bidi and font
/// fallback, letter- and word-spacing applied, the baseline's start at
/// `origin` (its end for right-to-left text), y down.
Path text_to_path(FontDatabase& fonts, std::string_view utf8, const TextStyle& style,
                  Point origin = {}, TextDirection direction = TextDirection::Ltr);

/// The advance of that line, px.
double text_advance(FontDatabase& fonts, std::string_view utf8, const TextStyle& style,
                    TextDirection direction = TextDirection::Ltr);

} // namespace casteljau
