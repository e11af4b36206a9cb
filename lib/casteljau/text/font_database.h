// Font matching: which font file draws a family, weight, style and stretch,
// and which one draws a character the first choice lacks.
//
// fontconfig does the matching (its rules are the system's: aliases, the
// generic families serif, sans-serif, monospace, cursive, fantasy and
// system-ui, and per-character fallback through each font's charset). The
// system configuration honours FONTCONFIG_FILE, so a test or a user can
// point the database at a chosen set of fonts; an application can instead
// start from an empty database and add its own files and folders.
//
// Families are tried in the order given; the first that fontconfig finds
// under that very name (or as a generic family) wins, as in CSS Fonts 4,
// 5.1 "font family matching". When none does, the default family is used.
//
// A FontDatabase is safe to share between threads: its calls take a lock.
#pragma once

#include "casteljau/text/font.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

enum class FontStyle { Normal, Italic, Oblique };

/// What a piece of text asks of its font (CSS Fonts 4, 2).
struct FontQuery {
    std::vector<std::string> families; ///< in order of preference; generic names allowed
    int weight = 400;                  ///< 1 to 1000
    FontStyle style = FontStyle::Normal;
    int stretch = 100; ///< percent of normal width, 50 to 200
};

/// Whether two family names are the same: equal but for ASCII case (CSS
/// Fonts 4, 5.1).
bool same_family_name(std::string_view a, std::string_view b);

/// A font file and the face in it: what a Font is loaded from.
struct FontFace {
    std::string file; ///< the file; for a font in memory, its name in messages
    int index = 0;
    /// A font in memory (a document's \@font-face): its bytes; null for a file.
    std::shared_ptr<const std::vector<unsigned char>> data;
    /// Bold or italic the face lacks, drawn anyway (the match's: fontconfig's
    /// for the system's fonts, FontSynthesis's rule for a document's).
    FontSynthesis synthesis;
    bool operator==(const FontFace&) const = default; ///< same file (or bytes), face and synthesis
};

/// What a document's font (CSS \@font-face) is for: its family, weights and style.
struct FontFaceDescriptors {
    std::string family;
    int weight_min = 400, weight_max = 400; ///< font-weight, a range (CSS Fonts 4, 4.2)
    FontStyle style = FontStyle::Normal;
};

/// Finds fonts and keeps them loaded.
class FontDatabase {
  public:
    /// The system's fonts, as fontconfig's configuration has them
    /// (FONTCONFIG_FILE honoured).
    FontDatabase();
    /// No fonts at all: an application adds its own.
    static std::unique_ptr<FontDatabase> empty();
    /// A document's fonts over `parent`'s (which must outlive it): the faces
    /// add_font_data gives are matched first, family by family in a query's
    /// order (CSS Fonts 4, 4.1: \@font-face families hide system ones of the
    /// same name); every other family, and fallback by character, is the
    /// parent's. A document layer keeps nothing in the parent, so documents
    /// read side by side never see each other's fonts.
    static std::unique_ptr<FontDatabase> layer(FontDatabase& parent);
    ~FontDatabase();
    FontDatabase(const FontDatabase&) = delete;
    FontDatabase& operator=(const FontDatabase&) = delete;

    /// Adds every font under `dir`; false when it is not a readable folder.
    bool add_font_dir(const std::string& dir);
    /// Adds one font file; false when fontconfig cannot read it.
    bool add_font_file(const std::string& file);
    /// Adds a font held in memory (TrueType, OpenType, WOFF or WOFF2) for
    /// the family and style of `d`; on a layer only. False, with `error`
    /// set, when it does not load as a font.
    bool add_font_data(const FontFaceDescriptors& d,
                       std::shared_ptr<const std::vector<unsigned char>> data, std::string& error);
    /// The family used when none of a query's families is found and
    /// fontconfig classes none of them in a generic family ("sans-serif"
    /// unless set: what fontconfig itself falls back to, as librsvg and
    /// resvg do; browsers take serif).
    void set_default_family(std::string family);
    /// The family set_default_family gave.
    const std::string& default_family() const { return default_family_; }

    /// The best face for a query; nullopt only when the database has no font.
    std::optional<FontFace> match(const FontQuery& q);
    /// The best face for a query that has a glyph for `c`; nullopt when no
    /// font has one.
    std::optional<FontFace> fallback(const FontQuery& q, char32_t c);
    /// The loaded font of a face and variation, shared and kept for the
    /// database's life; null when the file does not parse as a font.
    std::shared_ptr<const Font> font(const FontFace& face,
                                     const std::vector<FontVariation>& variations = {});

    /// The database shared by the SVG reader and the CLI when they are given
    /// none: the system's fonts, plus what add_font_dir gave it.
    static FontDatabase& system();

  private:
    explicit FontDatabase(bool system_config);
    explicit FontDatabase(FontDatabase* parent); // a layer
    std::optional<FontFace> find(const FontQuery& q, std::optional<char32_t> c);
    // The best face of `family` itself (or of a generic family), when one has c.
    std::optional<FontFace> find_family(const std::string& family, const FontQuery& q,
                                        std::optional<char32_t> c);
    struct Impl;
    struct Layer; // a layer's own faces (text/font_face_layer.cpp)
    std::unique_ptr<Impl> impl_;
    std::unique_ptr<Layer> layer_;
    FontDatabase* parent_ = nullptr; // a layer's
    std::string default_family_ = "sans-serif";
    std::mutex mutex_;
};

} // namespace casteljau
