// A loaded font: its metrics and its glyphs' outlines, read with FreeType.
//
// Outlines are in font units with y up, as the font stores them: TrueType
// glyphs are quadratic Beziers, CFF and CFF2 glyphs cubic ones, kept as such
// in a Path so that text goes through the same flattener and rasterizer, to
// the same error bound, as every other curve. They are never hinted (SVG's
// text-rendering: geometricPrecision is what every value gets). Each glyph
// is read once per font and variation and kept: a page of text does not
// re-read the font.
//
// Variable fonts: `variations` sets design axes by tag (wght, wdth, slnt,
// ital, opsz or the font's own), clamped to each axis's range; axes the
// font does not have are ignored.
#pragma once

#include "casteljau/curve/path.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

struct hb_face_t; // HarfBuzz's face (hb.h), for Font's loader

namespace casteljau {

struct FontFace;

/// Why no font can be read or matched: FreeType, HarfBuzz, fontconfig or
/// FriBidi could not be loaded (they are opened on first use, not linked);
/// empty when they are there. The first call loads them.
const std::string& text_libraries_error();

/// A design axis setting: a four-letter tag and a value.
struct FontVariation {
    char tag[4] = {' ', ' ', ' ', ' '};
    double value = 0;
    bool operator==(const FontVariation&) const = default; ///< same tag and value
};

/// What a face lacks and is drawn with anyway (CSS Fonts 4, 3.9
/// font-synthesis, whose initial value allows both): bold text in a family
/// without a bold face, italic text in one without an italic or oblique
/// face. As fontconfig's 90-synthetic.conf asks and cairo draws it (and so
/// librsvg): emboldened outlines, grown by 1/24 em (FreeType's
/// FT_GlyphSlot_Embolden), and outlines slanted, x + slant y in font units
/// (fontconfig's 0.2, 11.3 degrees). Advances stay the font's (HarfBuzz's),
/// as Pango and Chrome keep them.
struct FontSynthesis {
    bool bold = false;
    double slant = 0;
    bool operator==(const FontSynthesis&) const = default; ///< the same synthesis
};

/// Vertical metrics in font units, y up (descender negative).
struct FontMetrics {
    double units_per_em = 1000;
    double ascender = 800, descender = -200;
    double x_height = 500, cap_height = 700;
    double underline_position = -100, underline_thickness = 50; ///< position: the line's centre
    double strikeout_position = 250, strikeout_thickness = 50;  ///< position: the line's centre
};

/// A font file's face, loaded: metrics, glyph lookup and cached outlines.
class Font {
  public:
    /// Loads face `index` of `file`; null, with `error` set, when it does not
    /// parse as a font or is over the limits below.
    static std::shared_ptr<Font> load(const std::string& file, int index,
                                      const std::vector<FontVariation>& variations,
                                      std::string* error = nullptr);
    /// Loads face `index` of a font held in memory (TrueType, OpenType, a
    /// collection, WOFF or WOFF2: what FreeType reads), kept alive by the
    /// font; `name` stands for the file in `error`.
    static std::shared_ptr<Font> load(std::shared_ptr<const std::vector<unsigned char>> data,
                                      const std::string& name, int index,
                                      const std::vector<FontVariation>& variations,
                                      std::string* error = nullptr);
    ~Font();
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    /// Its vertical metrics, font units.
    const FontMetrics& metrics() const { return metrics_; }
    /// Its family name, as the font gives it.
    const std::string& family() const { return family_; }
    /// The glyph for a character; 0 (the missing glyph) when there is none.
    std::uint32_t glyph_index(char32_t c) const;
    /// The glyph's outline in font units, y up; empty for a glyph without
    /// one (a space) or that does not read. Thread-safe; kept once read.
    const Path& outline(std::uint32_t glyph) const;
    /// The glyph's horizontal advance in font units.
    double advance(std::uint32_t glyph) const;
    /// The glyph's vertical advance in font units (HarfBuzz's: the font's
    /// vertical metrics, else its ascender to its descender).
    double vertical_advance(std::uint32_t glyph) const;
    /// Where the glyph's vertical origin is from its horizontal one, font
    /// units, y up: what sits on the line of upright vertical text (the VORG
    /// table, else half the advance across and the ascender up).
    Vec2 vertical_origin(std::uint32_t glyph) const;
    /// How many glyphs it has.
    std::size_t glyph_count() const { return glyph_count_; }
    /// Whether the font is variable along the design axis `tag` ("wght").
    bool has_axis(const char tag[4]) const;
    /// Its outlines drawn bold or slanted though the face is not (the
    /// synthesis of a match, FontFace::synthesis); set once, before the
    /// first outline is read and the font is shared.
    void set_synthesis(const FontSynthesis& s) { synthesis_ = s; }
    /// What set_synthesis set.
    const FontSynthesis& synthesis() const { return synthesis_; }

    /// The most points a glyph outline can have: FreeType 2.12 (Debian 12)
    /// counts them in a signed short, and fails to load a glyph with more,
    /// so a hostile font cannot make one glyph cost unbounded time.
    static constexpr int kMaxOutlinePoints = 32767;

    struct Impl; ///< FreeType and HarfBuzz handles (text/detail/font_impl.h)
    Impl& impl() const { return *impl_; }

  private:
    Font() = default;
    // Loads the face FreeType opened into impl_ (from a file or memory);
    // `tables` gives HarfBuzz the face's tables.
    static std::shared_ptr<Font> finish(std::shared_ptr<Font> font,
                                        const std::vector<FontVariation>& variations,
                                        hb_face_t* tables);
    std::unique_ptr<Impl> impl_;
    FontMetrics metrics_;
    std::string family_;
    std::size_t glyph_count_ = 0;
    std::vector<std::uint32_t> axes_; // design axis tags, big-endian packed
    FontSynthesis synthesis_;
    mutable std::mutex mutex_; // FreeType faces are not thread-safe
    mutable std::unordered_map<std::uint32_t, Path> outlines_;
};

} // namespace casteljau
