// Font matching with fontconfig (see font_database.h).
//
// For each family of a query in turn, fontconfig's best match for that
// family, weight, slant and width is taken when it really is that family (a
// font of another family means fontconfig fell back: the next family is
// tried, as CSS Fonts 4, 5.1 asks) or when the family is generic, which
// fontconfig resolves through the system's aliases. When none of the
// families is there, the generic family fontconfig's configuration classes
// the first of them in (its `<default>` aliases, e.g. 45-latin.conf: Courier
// New monospace, Times New Roman and Palatino serif), as librsvg gets it from
// fontconfig; a family fontconfig knows nothing of gets its catch-all class
// (49-sansserif.conf), and then the database's default family is taken
// instead, which the application may set. A character's fallback
// is the first font of fontconfig's sorted list for the query whose charset
// has the character. Results are cached per query: matching is the costly
// part of fontconfig, and a document asks the same few queries again and again.
#include "casteljau/text/font_database.h"

#include "casteljau/text/detail/document_fonts.h"
#include "casteljau/text/detail/text_libs.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

namespace casteljau {

struct FontDatabase::Impl {
    FcConfig* config = nullptr;
    using Key = std::tuple<std::vector<std::string>, int, int, int, char32_t>;
    std::map<Key, std::optional<FontFace>> matches;
    // fontconfig's answers per family, weight, style and stretch: its best
    // match (null for none), and all its fonts sorted by closeness, which
    // each character's fallback then scans (its charsets are cheap to test;
    // the sort is what costs).
    using FamilyKey = std::tuple<std::string, int, int, int>;
    std::map<FamilyKey, FcPattern*> best;
    // The fonts sorted, and the query they answer (for their synthesis).
    std::map<FamilyKey, std::pair<FcPattern*, FcFontSet*>> sorted;
    std::map<std::string, std::string> generic_of; // see implied_generic
    // Loaded fonts by file, face, design axes and synthesis.
    using FontKey =
        std::tuple<std::string, int, std::vector<std::tuple<std::string, double>>, bool, double>;
    std::map<FontKey, std::shared_ptr<const Font>> fonts;

    FcPattern* best_of(const std::string& family, const FontQuery& q);
    std::pair<FcPattern*, FcFontSet*> sorted_of(const std::string& family, const FontQuery& q);
    std::optional<FontFace> match_family(const std::string& family, const FontQuery& q,
                                         std::optional<char32_t> c);
    std::optional<FontFace> closest(const std::string& family, const FontQuery& q,
                                    std::optional<char32_t> c);
    const std::string& implied_generic(const std::string& family);
    void forget() {
        matches.clear();
        generic_of.clear();
        for (auto& [k, p] : best)
            if (p) text_libs().FcPatternDestroy(p);
        for (auto& [k, query_and_set] : sorted) {
            text_libs().FcPatternDestroy(query_and_set.first);
            if (query_and_set.second) text_libs().FcFontSetDestroy(query_and_set.second);
        }
        best.clear();
        sorted.clear();
    }
    ~Impl() {
        forget();
        if (config) text_libs().FcConfigDestroy(config);
    }
};

namespace {

bool generic(const std::string& family) {
    for (const char* g : {"serif", "sans-serif", "monospace", "cursive", "fantasy", "system-ui",
                          "ui-serif", "ui-sans-serif", "ui-monospace", "math", "emoji"})
        if (family == g) return true;
    return false;
}

bool has_family(FcPattern* p, const std::string& family) {
    FcChar8* name = nullptr;
    for (int i = 0; text_libs().FcPatternGetString(p, FC_FAMILY, i, &name) == FcResultMatch; ++i)
        if (same_family_name(reinterpret_cast<const char*>(name), family)) return true;
    return false;
}

bool has_char(FcPattern* p, char32_t c) {
    FcCharSet* cs = nullptr;
    return text_libs().FcPatternGetCharSet(p, FC_CHARSET, 0, &cs) == FcResultMatch &&
           text_libs().FcCharSetHasChar(cs, c);
}

// The face a match names, with the synthesis fontconfig's rules for fonts
// (target="font", 90-synthetic.conf on most systems) put in it: FC_EMBOLDEN,
// and FC_MATRIX's shear (xy; its other entries are not synthesis).
std::optional<FontFace> face_of(FcPattern* p) {
    FcChar8* file = nullptr;
    int index = 0;
    if (text_libs().FcPatternGetString(p, FC_FILE, 0, &file) != FcResultMatch) return std::nullopt;
    text_libs().FcPatternGetInteger(p, FC_INDEX, 0, &index);
    FontFace face{reinterpret_cast<const char*>(file), index, nullptr, {}};
    FcBool embolden = FcFalse;
    face.synthesis.bold =
        text_libs().FcPatternGetBool(p, FC_EMBOLDEN, 0, &embolden) == FcResultMatch && embolden;
    FcMatrix* m = nullptr;
    if (text_libs().FcPatternGetMatrix(p, FC_MATRIX, 0, &m) == FcResultMatch && m &&
        std::isfinite(m->xy))
        face.synthesis.slant = std::clamp(m->xy, -1.0, 1.0); // 45 degrees at most
    return face;
}

// The pattern of one family of a query, with fontconfig's substitutions.
FcPattern* pattern_of(FcConfig* config, const std::string& family, const FontQuery& q) {
    FcPattern* p = text_libs().FcPatternCreate();
    // system-ui has no fontconfig alias on most systems: its closest is sans-serif.
    const std::string name = family == "system-ui" || family == "ui-sans-serif" ? "sans-serif"
                             : family == "ui-serif"                             ? "serif"
                             : family == "ui-monospace"                         ? "monospace"
                                                                                : family;
    text_libs().FcPatternAddString(p, FC_FAMILY, reinterpret_cast<const FcChar8*>(name.c_str()));
    text_libs().FcPatternAddDouble(p, FC_WEIGHT, text_libs().FcWeightFromOpenTypeDouble(q.weight));
    text_libs().FcPatternAddInteger(p, FC_SLANT,
                                    q.style == FontStyle::Italic    ? FC_SLANT_ITALIC
                                    : q.style == FontStyle::Oblique ? FC_SLANT_OBLIQUE
                                                                    : FC_SLANT_ROMAN);
    text_libs().FcPatternAddInteger(p, FC_WIDTH,
                                    q.stretch); // fontconfig's widths are CSS's percentages
    text_libs().FcPatternAddBool(p, FC_OUTLINE, FcTrue);
    text_libs().FcConfigSubstitute(config, p, FcMatchPattern);
    text_libs().FcDefaultSubstitute(p);
    return p;
}

} // namespace

bool same_family_name(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

FcPattern* FontDatabase::Impl::best_of(const std::string& family, const FontQuery& q) {
    const FamilyKey key{family, q.weight, int(q.style), q.stretch};
    if (const auto it = best.find(key); it != best.end()) return it->second;
    FcPattern* p = pattern_of(config, family, q);
    FcResult result;
    FcPattern* m = text_libs().FcFontMatch(config, p, &result);
    text_libs().FcPatternDestroy(p);
    return best[key] = m;
}

std::pair<FcPattern*, FcFontSet*> FontDatabase::Impl::sorted_of(const std::string& family,
                                                                const FontQuery& q) {
    const FamilyKey key{family, q.weight, int(q.style), q.stretch};
    if (const auto it = sorted.find(key); it != sorted.end()) return it->second;
    FcPattern* p = pattern_of(config, family, q);
    FcResult result;
    FcFontSet* set = text_libs().FcFontSort(config, p, FcFalse, nullptr, &result);
    return sorted[key] = {p, set};
}

// The first generic family in fontconfig's substitutions of `family` (its
// configuration's aliases); "" where there is none, or where it is the one
// fontconfig gives any family (its catch-all).
const std::string& FontDatabase::Impl::implied_generic(const std::string& family) {
    if (const auto it = generic_of.find(family); it != generic_of.end()) return it->second;
    const auto first_generic = [&](const std::string& name) {
        FcPattern* p = text_libs().FcPatternCreate();
        text_libs().FcPatternAddString(p, FC_FAMILY,
                                       reinterpret_cast<const FcChar8*>(name.c_str()));
        text_libs().FcConfigSubstitute(config, p, FcMatchPattern);
        std::string found;
        FcChar8* f = nullptr;
        for (int i = 1;
             found.empty() && text_libs().FcPatternGetString(p, FC_FAMILY, i, &f) == FcResultMatch;
             ++i)
            if (generic(reinterpret_cast<const char*>(f))) found = reinterpret_cast<const char*>(f);
        text_libs().FcPatternDestroy(p);
        return found;
    };
    std::string g = generic(family) ? "" : first_generic(family);
    // A name no configuration mentions: fontconfig's catch-all class.
    if (!g.empty() && g == first_generic("casteljau: no such family")) g.clear();
    return generic_of[family] = g;
}

// The best font of `family` for the query, when it is that family (or the
// family is generic) and has `c`, when given.
std::optional<FontFace> FontDatabase::Impl::match_family(const std::string& family,
                                                         const FontQuery& q,
                                                         std::optional<char32_t> c) {
    FcPattern* m = best_of(family, q);
    if (m && (generic(family) || has_family(m, family)) && (!c || has_char(m, *c)))
        return face_of(m);
    return std::nullopt;
}

// The first font, in fontconfig's order of closeness to the query, that
// has `c`; without `c`, the closest font of all.
std::optional<FontFace> FontDatabase::Impl::closest(const std::string& family, const FontQuery& q,
                                                    std::optional<char32_t> c) {
    const auto [query, set] = sorted_of(family, q);
    if (set)
        for (int i = 0; i < set->nfont; ++i)
            if (!c || has_char(set->fonts[i], *c)) {
                // A sorted font is the font's own pattern: fontconfig's
                // rules for fonts (its synthesis) apply once it is chosen.
                FcPattern* prepared = text_libs().FcFontRenderPrepare(config, query, set->fonts[i]);
                std::optional<FontFace> face = face_of(prepared ? prepared : set->fonts[i]);
                if (prepared) text_libs().FcPatternDestroy(prepared);
                return face;
            }
    return std::nullopt;
}

FontDatabase::FontDatabase() : FontDatabase(true) {}

FontDatabase::FontDatabase(bool system_config) : impl_(std::make_unique<Impl>()) {
    if (!text_libs().loaded()) return; // no configuration: no font matches
    text_libs().FcInit();
    impl_->config =
        system_config ? text_libs().FcInitLoadConfigAndFonts() : text_libs().FcConfigCreate();
    // An empty configuration still needs a cache folder, or fontconfig
    // complains of each folder added (and rescans it every time).
    if (!system_config)
        text_libs().FcConfigParseAndLoadFromMemory(
            impl_->config,
            reinterpret_cast<const FcChar8*>(
                "<fontconfig><cachedir prefix=\"xdg\">fontconfig</cachedir></fontconfig>"),
            FcFalse);
}

std::unique_ptr<FontDatabase> FontDatabase::empty() {
    return std::unique_ptr<FontDatabase>(new FontDatabase(false));
}

FontDatabase::FontDatabase(FontDatabase* parent)
    : impl_(std::make_unique<Impl>()), layer_(std::make_unique<Layer>()), parent_(parent) {}

std::unique_ptr<FontDatabase> FontDatabase::layer(FontDatabase& parent) {
    return std::unique_ptr<FontDatabase>(new FontDatabase(&parent));
}

bool FontDatabase::add_font_data(const FontFaceDescriptors& d,
                                 std::shared_ptr<const std::vector<unsigned char>> data,
                                 std::string& error) {
    if (!layer_) {
        error = "fonts in memory go to a document layer (FontDatabase::layer)";
        return false;
    }
    std::lock_guard lock(mutex_);
    // A name unique in the layer: the key of its loaded fonts.
    FontFace face{"@font-face " + std::to_string(layer_->entries.size() + 1) + " (" + d.family +
                      ")",
                  0,
                  std::move(data),
                  {}};
    std::shared_ptr<const Font> font = Font::load(face.data, face.file, 0, {}, &error);
    if (!font) return false;
    impl_->fonts[{face.file, face.index, {}, false, 0.0}] = font;
    layer_->entries.push_back({d, std::move(face), std::move(font)});
    impl_->forget();
    return true;
}

FontDatabase::~FontDatabase() = default;

FontDatabase& FontDatabase::system() {
    static FontDatabase db;
    return db;
}

bool FontDatabase::add_font_dir(const std::string& dir) {
    if (!impl_->config) return false; // a layer has no folders
    std::error_code e;
    if (!std::filesystem::is_directory(dir, e)) return false; // fontconfig would say yes
    std::lock_guard lock(mutex_);
    impl_->forget();
    return text_libs().FcConfigAppFontAddDir(impl_->config,
                                             reinterpret_cast<const FcChar8*>(dir.c_str()));
}

bool FontDatabase::add_font_file(const std::string& file) {
    if (!impl_->config) return false;
    std::lock_guard lock(mutex_);
    impl_->forget();
    return text_libs().FcConfigAppFontAddFile(impl_->config,
                                              reinterpret_cast<const FcChar8*>(file.c_str()));
}

void FontDatabase::set_default_family(std::string family) {
    std::lock_guard lock(mutex_);
    impl_->forget();
    default_family_ = std::move(family);
}

std::optional<FontFace> FontDatabase::match(const FontQuery& q) { return find(q, std::nullopt); }

std::optional<FontFace> FontDatabase::fallback(const FontQuery& q, char32_t c) {
    return find(q, c);
}

std::optional<FontFace> FontDatabase::find_family(const std::string& family, const FontQuery& q,
                                                  std::optional<char32_t> c) {
    std::lock_guard lock(mutex_);
    if (parent_) {
        if (const Layer::Entry* e = layer_->best(family, q, c)) return Layer::face_for(*e, q);
        return parent_->find_family(family, q, c);
    }
    if (!impl_->config) return std::nullopt; // the text libraries did not load
    return impl_->match_family(family, q, c);
}

std::optional<FontFace> FontDatabase::find(const FontQuery& q, std::optional<char32_t> c) {
    std::lock_guard lock(mutex_);
    const Impl::Key key{q.families, q.weight, int(q.style), q.stretch, c ? *c + 1 : 0};
    if (const auto it = impl_->matches.find(key); it != impl_->matches.end()) return it->second;
    std::optional<FontFace> face;
    if (parent_) { // a layer: its families, or the parent's, in the query's order
        for (const std::string& family : q.families) {
            if (const Layer::Entry* e = layer_->best(family, q, c)) face = Layer::face_for(*e, q);
            if (face || (face = parent_->find_family(family, q, c))) break;
        }
        if (!face) face = parent_->find(q, c);
        impl_->matches.emplace(key, face);
        return face;
    }
    if (!impl_->config) return std::nullopt; // the text libraries did not load
    for (const std::string& family : q.families)
        if ((face = impl_->match_family(family, q, c))) break;
    for (const std::string& family : q.families) {
        if (face) break;
        if (const std::string& g = impl_->implied_generic(family); !g.empty())
            face = impl_->match_family(g, q, c);
    }
    if (!face) face = impl_->match_family(default_family_, q, c);
    if (!face) face = impl_->closest(q.families.empty() ? default_family_ : q.families[0], q, c);
    impl_->matches.emplace(key, face);
    return face;
}

std::shared_ptr<const Font> FontDatabase::font(const FontFace& face,
                                               const std::vector<FontVariation>& variations) {
    if (parent_ && !face.data) return parent_->font(face, variations);
    std::lock_guard lock(mutex_);
    std::vector<std::tuple<std::string, double>> axes;
    for (const FontVariation& v : variations) axes.emplace_back(std::string(v.tag, 4), v.value);
    auto& slot =
        impl_->fonts[{face.file, face.index, axes, face.synthesis.bold, face.synthesis.slant}];
    if (!slot) {
        std::shared_ptr<Font> f = face.data
                                      ? Font::load(face.data, face.file, face.index, variations)
                                      : Font::load(face.file, face.index, variations);
        if (f) f->set_synthesis(face.synthesis);
        slot = std::move(f);
    }
    return slot;
}

} // namespace casteljau
