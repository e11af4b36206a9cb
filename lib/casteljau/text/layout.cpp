// Paragraph shaping and one-line layout (see layout.h).
#include "casteljau/text/layout.h"

#include "casteljau/text/bidi.h"
#include "casteljau/text/detail/text_libs.h"
#include "casteljau/text/utf8.h"

#include <algorithm>
#include <map>

namespace casteljau {

namespace {

bool is_mark(char32_t c) {
    if (!text_libs().loaded()) return false;
    const hb_unicode_general_category_t cat =
        text_libs().hb_unicode_general_category(text_libs().hb_unicode_funcs_get_default(), c);
    return cat == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK ||
           cat == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK ||
           cat == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK;
}

// Characters no font needs a glyph for: controls, joiners, variation
// selectors, the bidi marks. They stay with the font around them.
bool is_invisible(char32_t c) {
    return c < 0x20 || (c >= 0x200B && c <= 0x200F) || (c >= 0x202A && c <= 0x202E) ||
           (c >= 0x2060 && c <= 0x206F) || (c >= 0xFE00 && c <= 0xFE0F) || c == 0xFEFF;
}

// A face loaded for a style: on a variable font, font-weight and
// font-stretch set the wght and wdth axes unless font-variation-settings
// does (CSS Fonts 4, 7.2: the settings apply last).
std::shared_ptr<const Font> load(FontDatabase& db, const FontFace& face, const TextStyle& s) {
    std::shared_ptr<const Font> f = db.font(face, s.variations);
    if (!f) return f;
    std::vector<FontVariation> v = s.variations;
    const auto set = [&](const char tag[4], double value) {
        for (const FontVariation& x : v)
            if (std::equal(tag, tag + 4, x.tag)) return false;
        if (!f->has_axis(tag)) return false;
        v.insert(v.begin(), FontVariation{{tag[0], tag[1], tag[2], tag[3]}, value});
        return true;
    };
    const bool weight = set("wght", s.font.weight);
    const bool width = set("wdth", s.font.stretch);
    return weight || width ? db.font(face, v) : f;
}

// The font of each character (CSS Fonts 4, 5.2): the style's first match
// when it has the character, else the font fontconfig falls back to for it;
// a mark or an invisible character takes its base's font when that has it.
std::vector<std::shared_ptr<const Font>> fonts_of(FontDatabase& db, std::u32string_view text,
                                                  const std::vector<TextStyle>& styles,
                                                  const std::vector<std::uint32_t>& style_of) {
    // Only the styles the text uses: a caller may hand all of a document's.
    std::vector<std::shared_ptr<const Font>> primary(styles.size());
    std::vector<bool> matched(styles.size());
    for (const std::uint32_t s : style_of) {
        if (matched[s]) continue;
        matched[s] = true;
        if (const auto face = db.match(styles[s].font)) primary[s] = load(db, *face, styles[s]);
    }
    std::map<std::pair<std::uint32_t, char32_t>, std::shared_ptr<const Font>> fallbacks;
    std::vector<std::shared_ptr<const Font>> fonts(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        const std::uint32_t s = style_of[i];
        const char32_t c = text[i];
        const auto has = [&](const std::shared_ptr<const Font>& f) {
            return f && f->glyph_index(c) != 0;
        };
        if (i > 0 && style_of[i - 1] == s && (is_mark(c) || is_invisible(c)) &&
            (has(fonts[i - 1]) || is_invisible(c))) {
            fonts[i] = fonts[i - 1];
            continue;
        }
        if (has(primary[s]) || is_invisible(c)) {
            fonts[i] = primary[s];
            continue;
        }
        auto& f = fallbacks[{s, c}];
        if (!f)
            if (const auto face = db.fallback(styles[s].font, c)) f = load(db, *face, styles[s]);
        fonts[i] = has(f) ? f : primary[s]; // none has it: the style's missing glyph
    }
    return fonts;
}

bool same_shaping(const TextStyle& a, const TextStyle& b) {
    const auto same_features = [](const std::vector<FontFeature>& x,
                                  const std::vector<FontFeature>& y) {
        return std::equal(x.begin(), x.end(), y.begin(), y.end(),
                          [](const FontFeature& f, const FontFeature& g) {
                              return std::equal(f.tag, f.tag + 4, g.tag) && f.on == g.on;
                          });
    };
    return a.size == b.size && a.size_adjust == b.size_adjust && a.language == b.language &&
           same_features(a.features, b.features);
}

double scale_of(const TextStyle& s, const Font& f) {
    const FontMetrics& m = f.metrics();
    double size = s.size;
    if (s.size_adjust && m.x_height > 0) size *= *s.size_adjust / (m.x_height / m.units_per_em);
    return size / m.units_per_em;
}

// One item's glyphs, shaped and converted to pixels.
// Each glyph names the style of its cluster's first character: an item may
// hold several styles that shape alike (the spans of one font and size).
void shape_item(std::u32string_view text, std::size_t begin, std::size_t end, bool rtl,
                const std::shared_ptr<const Font>& font, const TextStyle& style,
                const std::vector<std::uint32_t>& style_of, std::vector<LaidGlyph>& out) {
    if (!font) { // no font at all: the characters take no room
        out.push_back({nullptr, 0, begin, end, true, style_of[begin], 0, {}, {}, rtl});
        return;
    }
    ShapeOptions options{rtl ? TextDirection::Rtl : TextDirection::Ltr, style.language,
                         style.features};
    const std::vector<ShapedGlyph> glyphs = shape_run(*font, text, begin, end, options);
    // Each cluster ends where the next larger one starts (or the item ends).
    std::vector<std::uint32_t> starts;
    for (const ShapedGlyph& g : glyphs) starts.push_back(g.cluster);
    std::sort(starts.begin(), starts.end());
    starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
    const double k = scale_of(style, *font);
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
        const ShapedGlyph& g = glyphs[i];
        const auto next = std::upper_bound(starts.begin(), starts.end(), g.cluster);
        const std::size_t cluster_end = next == starts.end() ? end : *next;
        const bool first = i == 0 || glyphs[i - 1].cluster != g.cluster;
        out.push_back({font, g.glyph, g.cluster, cluster_end, first, style_of[g.cluster], k,
                       Vec2{g.x_advance * k, -g.y_advance * k},
                       Vec2{g.x_offset * k, -g.y_offset * k}, rtl});
    }
}

} // namespace

std::vector<LaidGlyph> shape_paragraph(FontDatabase& fonts, std::u32string_view text,
                                       const std::vector<TextStyle>& styles,
                                       const std::vector<std::uint32_t>& style_of,
                                       TextDirection direction,
                                       const std::vector<std::uint8_t>* given) {
    std::vector<LaidGlyph> out;
    if (text.empty() || styles.empty() || style_of.size() != text.size() ||
        (given && given->size() != text.size()))
        return out;
    const std::vector<std::shared_ptr<const Font>> font = fonts_of(fonts, text, styles, style_of);
    const std::vector<std::uint8_t> levels =
        given                             ? *given
        : direction == TextDirection::Ttb ? std::vector<std::uint8_t>(text.size(), 0)
                                          : bidi_levels(text, direction == TextDirection::Rtl);
    for (const BidiRun& run : visual_runs(levels)) {
        // Items: maximal ranges of one font and one way of shaping.
        std::vector<std::pair<std::size_t, std::size_t>> items;
        for (std::size_t i = run.begin; i < run.end;) {
            std::size_t j = i + 1;
            while (j < run.end && font[j] == font[i] &&
                   same_shaping(styles[style_of[j]], styles[style_of[i]]))
                ++j;
            items.emplace_back(i, j);
            i = j;
        }
        if (run.rtl()) std::reverse(items.begin(), items.end());
        for (const auto& [b, e] : items)
            shape_item(text, b, e, run.rtl(), font[b], styles[style_of[b]], style_of, out);
    }
    return out;
}

void append_glyph(Path& out, const LaidGlyph& g, const Affine& m) {
    if (!g.font) return;
    const Affine to = m * Affine::translate(g.offset) * Affine::scale(g.scale, -g.scale);
    for (const Subpath& sp : g.font->outline(g.glyph).subpaths()) {
        Subpath t{to * sp.start, {}, sp.closed};
        t.segments.reserve(sp.segments.size() + (sp.closed ? 1 : 0)); // + close()'s line
        for (const Segment& s : sp.segments) t.segments.push_back(segment_transformed(s, to));
        out.add_subpath(std::move(t));
    }
}

bool is_word_separator(char32_t c) {
    return c == 0x20 || c == 0xA0 || c == 0x1361 || c == 0x10100 || c == 0x10101 || c == 0x1039F ||
           c == 0x1091F;
}

namespace {

// The line's glyphs and each one's pen position from the line's start.
std::vector<std::pair<LaidGlyph, double>> set_line(FontDatabase& fonts, std::u32string_view text,
                                                   const TextStyle& style, TextDirection direction,
                                                   double& width) {
    const std::vector<LaidGlyph> glyphs = shape_paragraph(
        fonts, text, {style}, std::vector<std::uint32_t>(text.size(), 0), direction);
    std::vector<std::pair<LaidGlyph, double>> placed;
    double pen = 0;
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
        const LaidGlyph& g = glyphs[i];
        placed.emplace_back(g, pen);
        pen += g.advance.x;
        const bool cluster_ends = i + 1 == glyphs.size() || glyphs[i + 1].first;
        if (!cluster_ends) continue;
        pen += style.letter_spacing;
        if (g.end > g.begin && is_word_separator(text[g.begin])) pen += style.word_spacing;
    }
    width = pen;
    return placed;
}

} // namespace

Path text_to_path(FontDatabase& fonts, std::string_view utf8, const TextStyle& style, Point origin,
                  TextDirection direction) {
    const std::u32string text = decode_utf8(utf8);
    double width = 0;
    const auto placed = set_line(fonts, text, style, direction, width);
    const double x0 = direction == TextDirection::Rtl ? origin.x - width : origin.x;
    Path path;
    for (const auto& [g, pen] : placed)
        append_glyph(path, g, Affine::translate({x0 + pen, origin.y}));
    return path;
}

double text_advance(FontDatabase& fonts, std::string_view utf8, const TextStyle& style,
                    TextDirection direction) {
    double width = 0;
    set_line(fonts, decode_utf8(utf8), style, direction, width);
    return width;
}

} // namespace casteljau
