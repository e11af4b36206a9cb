// The text properties of SVG 2 (11.10) and CSS Fonts 4 / CSS Text 3 /
// CSS Inline 3 / CSS Writing Modes 3, their parsing and inheritance.
//
// Inherited properties live in TextState (a part of StyleState), the others
// in TextProps (a part of ElementProps); apply_property (svg/style.h) hands
// every text property to apply_text_property, with the same contract: an
// invalid value is ignored (the property keeps its inherited or initial
// value) and what is wrong is returned, for a warning.
//
// Computed values: font-weight is a number (bolder and lighter step as CSS
// Fonts 4, 2.2's table); letter-spacing and word-spacing are px (normal is 0;
// em and % against the element's font size); font-stretch is a percentage.
#pragma once

#include "casteljau/text/font_database.h"
#include "casteljau/text/shaping.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

struct StyleState;
struct ElementProps;
struct LengthContext;

enum class TextAnchor { Start, Middle, End };

/// dominant-baseline and alignment-baseline values (SVG 2, 11.10.2; CSS
/// Inline 3). Auto is alphabetic for horizontal text, central for vertical;
/// for alignment-baseline it means the parent's dominant baseline.
enum class Baseline {
    Auto,
    Alphabetic,
    Ideographic,
    Middle,
    Central,
    Mathematical,
    Hanging,
    TextBeforeEdge, ///< text-top too
    TextAfterEdge,  ///< text-bottom too
};

enum class WritingMode { HorizontalTb, VerticalRl, VerticalLr };

enum class UnicodeBidi { Normal, Embed, Isolate, BidiOverride, IsolateOverride, Plaintext };

/// baseline-shift: baseline (none), sub, super, or a length in px.
struct BaselineShift {
    /// Which of the four it is.
    enum class Kind { Baseline, Sub, Super, Length };
    Kind kind = Kind::Baseline; ///< which of the four
    double px = 0;              ///< for Length; a percentage is of the element's font size
};

/// text-decoration lines (CSS Text Decoration 3, 2.1).
struct TextDecorationLines {
    bool underline = false, overline = false, line_through = false;
    bool any() const { return underline || overline || line_through; } ///< at least one line
};

/// The inherited text properties, computed.
struct TextState {
    /// The initial value is the user agent's (CSS Fonts 4, 3.1): Times New
    /// Roman, as browsers' default font, librsvg's and resvg's (serif where
    /// the system lacks it, fontconfig's class for it). An empty list is the
    /// font database's default family.
    std::vector<std::string> font_family{"Times New Roman"};
    int font_weight = 400;
    FontStyle font_style = FontStyle::Normal;
    int font_stretch = 100;                 ///< percent
    bool small_caps = false;                ///< font-variant(-caps): small-caps
    bool kerning = true;                    ///< font-kerning: none turns it off
    std::vector<FontVariation> variations;  ///< font-variation-settings
    std::vector<FontFeature> features;      ///< font-feature-settings
    std::optional<double> font_size_adjust; ///< none when nullopt
    double letter_spacing = 0;              ///< px
    double word_spacing = 0;                ///< px
    TextAnchor anchor = TextAnchor::Start;
    Baseline dominant_baseline = Baseline::Auto;
    WritingMode writing_mode = WritingMode::HorizontalTb;
    bool rtl = false; ///< direction: rtl
    /// glyph-orientation-vertical: auto (-1), or 0 or 90 degrees.
    int glyph_orientation_vertical = -1;
    /// white-space (CSS Text 3, 3): pre, pre-wrap and break-spaces keep
    /// spaces, as xml:space="preserve" does; pre-line collapses them.
    bool preserve_spaces = false;
    /// The language of xml:lang or lang (BCP 47; inherited as attributes are
    /// by the language's own rule): HarfBuzz's choice of local forms.
    std::string language;
};

/// The text properties that are not inherited.
struct TextProps {
    Baseline alignment_baseline = Baseline::Auto;
    BaselineShift baseline_shift;
    UnicodeBidi unicode_bidi = UnicodeBidi::Normal;
    /// text-decoration(-line): not inherited, but drawn over the text of the
    /// descendants too, in the paint of the element that set it.
    TextDecorationLines decoration;
};

/// Applies a text property: nullopt when `name` is not one; "" when
/// applied; otherwise what is wrong with the value (then ignored). The
/// font shorthand sets font-size in `style` too.
std::optional<std::string> apply_text_property(std::string_view name, std::string_view value,
                                               const StyleState& parent, StyleState& style,
                                               ElementProps& props, const LengthContext& ctx);

/// A font-weight (CSS Fonts 4, 2.2): normal, bold, a number from 1 to 1000
/// (rounded), or bolder or lighter than `parent`; nullopt when invalid.
std::optional<int> parse_font_weight(std::string_view v, int parent);

/// A font-family list (CSS Fonts 4, 2.1): names, quoted or as identifier
/// sequences, separated by commas; nullopt when malformed.
std::optional<std::vector<std::string>> parse_font_family(std::string_view value);

} // namespace casteljau
