// Text layout of SVG 2, 11.8.3 ("the text layout algorithm"), simplified to
// what one line per chunk needs (SVG has no line breaking):
//   1. Chunks: a new one starts at each character with an absolute x or y,
//      and where a textPath starts or ends.
//   2. Each chunk is shaped as a paragraph (text/layout.h): bidi, fonts with
//      fallback, HarfBuzz; clusters come in visual order.
//   3. The pen walks the clusters in visual order; each is moved by the sum
//      of the dx and dy of the chunk's characters up to its last one, in
//      logical order; the pen advances by the cluster's advance, letter-spacing and,
//      after a word separator, word-spacing; textLength spreads what is left
//      over the gaps between clusters (lengthAdjust="spacing"), or scales
//      advances and glyphs along the line (spacingAndGlyphs).
//   4. text-anchor moves the chunk by its advance (all of it for end, half
//      for middle; start and end swap in right-to-left text).
//   5. Baselines: each span sits on its alignment-baseline (else the
//      dominant-baseline), read from its font's metrics, raised by its
//      baseline-shift (sub and super: 0.2 and 0.4 em, as librsvg and resvg).
//   6. On a textPath, x is a distance along the path: each cluster is set
//      where its middle falls, turned to the path's direction there, and
//      not drawn when its middle falls off the path (SVG 2, 11.8.3, step 8).
//   7. Vertical writing modes advance down the line; CJK characters stand
//      upright, others turn 90 degrees (glyph-orientation-vertical: auto).
#include "casteljau/curve/path_measure.h"
#include "casteljau/svg/detail/text_content.h"
#include "casteljau/svg/shapes.h"
#include "casteljau/text/bidi.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>

namespace casteljau::svg_detail {

TextStyle text_style(const StyleState& s) {
    TextStyle t;
    const TextState& ts = s.text;
    t.font = {ts.font_family, ts.font_weight, ts.font_style, ts.font_stretch};
    t.size = s.font_size;
    t.size_adjust = ts.font_size_adjust;
    t.variations = ts.variations;
    t.features = ts.features;
    if (!ts.kerning) t.features.push_back({{'k', 'e', 'r', 'n'}, false});
    if (ts.small_caps) t.features.push_back({{'s', 'm', 'c', 'p'}, true});
    t.letter_spacing = ts.letter_spacing;
    t.word_spacing = ts.word_spacing;
    t.language = ts.language;
    return t;
}

namespace {

// Characters set upright in vertical text (UAX #50's U class, roughly):
// Han, kana, Hangul, and the CJK symbols and full-width forms.
bool upright(char32_t c) {
    return (c >= 0x1100 && c <= 0x11FF) || (c >= 0x2E80 && c <= 0xA4CF) ||
           (c >= 0xAC00 && c <= 0xD7AF) || (c >= 0xF900 && c <= 0xFAFF) ||
           (c >= 0xFE30 && c <= 0xFE4F) || (c >= 0xFF00 && c <= 0xFFEF) ||
           (c >= 0x20000 && c <= 0x3FFFF);
}

struct Cluster {
    std::size_t g0 = 0, g1 = 0;     // its glyphs in the chunk's glyph list
    std::size_t begin = 0, end = 0; // its characters
    std::uint32_t span = 0;
    double advance = 0; // along the line, px, spacing included
    double stretch = 1; // spacingAndGlyphs
    double extra = 0;   // textLength's spacing after it
    Point pen;          // where its origin is, before anchoring
    bool upright = false;
};

class Layouter {
  public:
    Layouter(FontDatabase& fonts, const TextContent& c) : fonts_(fonts), c_(c) {
        for (const TextSpan& s : c.spans) styles_.push_back(text_style(s.style));
        primary_.resize(c.spans.size());
        measures_.resize(c.paths.size());
        for (std::size_t i = 0; i < c.spans.size(); ++i)
            if (const auto face = fonts.match(styles_[i].font))
                primary_[i] = fonts.font(*face, styles_[i].variations);
    }

    TextLayout run() {
        for (std::size_t b = 0; b < c_.chars.size();) {
            std::size_t e = b + 1;
            while (e < c_.chars.size() && !starts_chunk(e)) ++e;
            chunk(b, e);
            b = e;
        }
        return std::move(out_);
    }

  private:
    bool starts_chunk(std::size_t i) const {
        return c_.chars[i].x || c_.chars[i].y ||
               c_.spans[c_.chars[i].span].text_path != c_.spans[c_.chars[i - 1].span].text_path;
    }
    const TextSpan& span_of(std::size_t i) const { return c_.spans[c_.chars[i].span]; }
    bool vertical(std::size_t i) const {
        return span_of(i).style.text.writing_mode != WritingMode::HorizontalTb;
    }
    // px per font unit of a span's first font, and its metrics.
    double unit(std::uint32_t span) const {
        return primary_[span] ? styles_[span].size / primary_[span]->metrics().units_per_em : 0;
    }
    // The span's baseline below the line's alphabetic one, px (y down).
    double baseline(std::uint32_t span) const {
        const TextSpan& s = c_.spans[span];
        Baseline b = s.props.alignment_baseline != Baseline::Auto ? s.props.alignment_baseline
                                                                  : s.style.text.dominant_baseline;
        double up = 0;
        if (primary_[span]) {
            const FontMetrics& m = primary_[span]->metrics();
            switch (b) {
            case Baseline::Auto:
            case Baseline::Alphabetic:
                up = 0;
                break;
            case Baseline::Ideographic:
            case Baseline::TextAfterEdge:
                up = m.descender;
                break;
            case Baseline::Middle:
                up = m.x_height / 2;
                break;
            case Baseline::Central:
                up = (m.ascender + m.descender) / 2;
                break;
            case Baseline::Mathematical:
                up = m.ascender / 2;
                break;
            case Baseline::Hanging:
                up = m.ascender * 0.8;
                break; // as resvg, for fonts without BASE
            case Baseline::TextBeforeEdge:
                up = m.ascender;
                break;
            }
        }
        return up * unit(span) - s.baseline_shift;
    }

    std::vector<std::uint8_t> bidi_of(std::size_t b, std::size_t e, std::u32string_view text,
                                      TextDirection dir) const;
    std::vector<Cluster> clusters_of(const std::vector<LaidGlyph>& glyphs, bool vert) const;
    void apply_text_lengths(std::vector<Cluster>& cl) const;
    void chunk(std::size_t b, std::size_t e);
    void on_path(const std::vector<LaidGlyph>& glyphs, const std::vector<Cluster>& cl,
                 std::size_t path);
    void decorate(const DecorationPiece& d);
    void place(const std::vector<LaidGlyph>& glyphs, const Cluster& c, const Affine& at);

    FontDatabase& fonts_;
    const TextContent& c_;
    std::vector<TextStyle> styles_;
    std::vector<std::shared_ptr<const Font>> primary_;
    Point pen_;               // where the next chunk starts when it gives no x or y
    Point path_pen_;          // the same along a textPath: x a distance, y an offset
    std::vector<Vec2> shift_; // chunk(): each character's sum of dx and dy, kept between chunks
    std::vector<std::optional<PathMeasure>> measures_; // each textPath's, once needed
    // The last piece of each decoration line (owner, line) in out_, in this chunk.
    std::map<std::pair<std::uint32_t, int>, std::size_t> last_piece_;
    TextLayout out_;
};

// unicode-bidi (CSS Writing Modes 3, 2.2): each span that embeds,
// isolates or overrides wraps its content, its descendants' included, in
// the bidi control characters that do the same (LRE/RLE, LRI/RLI, LRO/RLO,
// FSI, closed by PDF or PDI), and the algorithm runs on that text; empty
// when no span asks for any.
std::vector<std::uint8_t> Layouter::bidi_of(std::size_t b, std::size_t e, std::u32string_view text,
                                            TextDirection dir) const {
    const auto controls = [&](std::uint32_t span, bool open) -> std::u32string {
        const TextSpan& s = c_.spans[span];
        const bool rtl = s.style.text.rtl;
        switch (s.props.unicode_bidi) {
        case UnicodeBidi::Normal:
            return U"";
        case UnicodeBidi::Embed:
            return open ? (rtl ? U"\u202B" : U"\u202A") : U"\u202C";
        case UnicodeBidi::BidiOverride:
            return open ? (rtl ? U"\u202E" : U"\u202D") : U"\u202C";
        case UnicodeBidi::Isolate:
            return open ? (rtl ? U"\u2067" : U"\u2066") : U"\u2069";
        case UnicodeBidi::Plaintext:
            return open ? U"\u2068" : U"\u2069";
        case UnicodeBidi::IsolateOverride:
            return open ? (rtl ? U"\u2067\u202E" : U"\u2066\u202D") : U"\u202C\u2069";
        }
        return U"";
    };
    const auto chain = [&](std::uint32_t span) { // the spans around a character, outermost first
        std::vector<std::uint32_t> c{span};
        while (c.back() != 0) c.push_back(c_.spans[c.back()].parent);
        std::reverse(c.begin(), c.end());
        return c;
    };
    if (dir == TextDirection::Ttb) return {};
    std::u32string marked;
    std::vector<std::size_t> at(e - b);
    std::vector<std::uint32_t> open;
    bool any = false;
    for (std::size_t i = b; i <= e; ++i) {
        const std::vector<std::uint32_t> now =
            i < e ? chain(c_.chars[i].span) : std::vector<std::uint32_t>{};
        std::size_t same = 0;
        while (same < open.size() && same < now.size() && open[same] == now[same]) ++same;
        for (std::size_t k = open.size(); k > same; --k) marked += controls(open[k - 1], false);
        for (std::size_t k = same; k < now.size(); ++k) {
            const std::u32string c = controls(now[k], true);
            any = any || !c.empty();
            marked += c;
        }
        open = now;
        if (i < e) at[i - b] = marked.size(), marked += text[i - b];
    }
    if (!any) return {};
    const std::vector<std::uint8_t> all = bidi_levels(marked, dir == TextDirection::Rtl);
    std::vector<std::uint8_t> levels(e - b);
    for (std::size_t i = 0; i < levels.size(); ++i) levels[i] = all[at[i]];
    return levels;
}

std::vector<Cluster> Layouter::clusters_of(const std::vector<LaidGlyph>& glyphs, bool vert) const {
    std::vector<Cluster> cl;
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
        const LaidGlyph& g = glyphs[i];
        if (g.first || cl.empty())
            cl.push_back({i, i, g.begin, g.end, c_.chars[g.begin].span, 0, 1, 0, {}, false});
        Cluster& c = cl.back();
        c.g1 = i + 1;
        const int orientation = c_.spans[c.span].style.text.glyph_orientation_vertical;
        c.upright = vert && (orientation == 0 || (orientation < 0 && upright(c_.chars[c.begin].c)));
        c.advance +=
            c.upright && g.font ? g.font->vertical_advance(g.glyph) * g.scale : g.advance.x;
    }
    for (Cluster& c : cl) {
        const TextStyle& s = styles_[c.span];
        c.advance += s.letter_spacing;
        if (is_word_separator(c_.chars[c.begin].c)) c.advance += s.word_spacing;
    }
    return cl;
}

void Layouter::apply_text_lengths(std::vector<Cluster>& cl) const {
    for (const TextLengthSpec& L : c_.lengths) {
        double natural = 0;
        std::size_t n = 0, last = 0;
        for (std::size_t i = 0; i < cl.size(); ++i)
            if (cl[i].begin >= L.begin && cl[i].begin < L.end)
                natural += cl[i].advance, ++n, last = i;
        if (n == 0 || natural <= 0) continue;
        for (std::size_t i = 0; i < cl.size(); ++i) {
            if (cl[i].begin < L.begin || cl[i].begin >= L.end) continue;
            if (L.glyphs)
                cl[i].stretch = L.length / natural;
            else if (n > 1 && i != last)
                cl[i].extra = (L.length - natural) / double(n - 1);
        }
    }
}

void Layouter::chunk(std::size_t b, std::size_t e) {
    last_piece_.clear();
    const bool vert = vertical(b);
    std::u32string text;
    std::vector<std::uint32_t> style_of;
    for (std::size_t i = b; i < e; ++i)
        text.push_back(c_.chars[i].c), style_of.push_back(c_.chars[i].span);
    const TextDirection dir = vert                         ? TextDirection::Ttb
                              : c_.spans[0].style.text.rtl ? TextDirection::Rtl
                                                           : TextDirection::Ltr;
    const std::vector<std::uint8_t> levels = bidi_of(b, e, text, dir);
    std::vector<LaidGlyph> glyphs =
        shape_paragraph(fonts_, text, styles_, style_of, dir, levels.empty() ? nullptr : &levels);
    for (LaidGlyph& g : glyphs) g.begin += b, g.end += b;
    std::vector<Cluster> cl = clusters_of(glyphs, vert);
    apply_text_lengths(cl);
    // On a path, x is a distance along it (SVG 1.1, 10.13.3), from 0 where
    // the path's text starts.
    const int path = span_of(b).text_path;
    const bool path_starts = path >= 0 && (b == 0 || span_of(b - 1).text_path != path);
    const Point from = path < 0 ? pen_ : path_starts ? Point{0, 0} : path_pen_;
    const Point start{c_.chars[b].x.value_or(from.x),
                      path >= 0 ? from.y : c_.chars[b].y.value_or(from.y)};
    // dx and dy add up in logical order (SVG 2, 11.8.3, step 4): character
    // i is moved by the sum of the moves of the chunk's characters up to i,
    // and a cluster by its last character's; the advances add up in visual
    // order. (In right-to-left text a dx on the first character moves the
    // whole chunk, not the cluster drawn last.)
    shift_.resize(e - b);
    Vec2 moved{0, 0};
    for (std::size_t i = b; i < e; ++i)
        shift_[i - b] = moved = moved + Vec2{c_.chars[i].dx, c_.chars[i].dy};
    Point pen = start;
    for (Cluster& c : cl) {
        c.pen = pen + shift_[c.end - 1 - b];
        const double step = c.advance * c.stretch + c.extra;
        pen = pen + (vert ? Vec2{0, step} : Vec2{step, 0});
    }
    pen = pen + moved;
    // text-anchor: the chunk moved by its advance, or half of it.
    const double length = vert ? pen.y - start.y : pen.x - start.x;
    // The anchor of the chunk's first character's element; the direction
    // of the paragraph, the text element's (CSS Writing Modes 3, 2.1: an
    // inline element's direction acts only through unicode-bidi).
    const TextState& ts = span_of(b).style.text;
    const bool rtl = c_.spans[0].style.text.rtl && !vert;
    const double shift = ts.anchor == TextAnchor::Middle         ? -length / 2
                         : (ts.anchor == TextAnchor::End) != rtl ? -length
                                                                 : 0;
    const Vec2 move = vert ? Vec2{0, shift} : Vec2{shift, 0};
    for (Cluster& c : cl) c.pen = c.pen + move;
    (path < 0 ? pen_ : path_pen_) = pen + move;
    if (path < 0) {
        for (const Cluster& c : cl) place(glyphs, c, Affine::translate(c.pen.to_vec()));
        return;
    }
    on_path(glyphs, cl, std::size_t(path));
}

// Each cluster where its middle falls on the path, turned to the path's
// direction there; not drawn when its middle falls off the path.
void Layouter::on_path(const std::vector<LaidGlyph>& glyphs, const std::vector<Cluster>& cl,
                       std::size_t path) {
    const TextPathRef& ref = c_.paths[path];
    if (!measures_[path]) {
        // Within 1e-5 of the path's size: positions far finer than a pixel
        // at any scale the path is seen at, in a bounded number of chords.
        const Rect box = ref.path.control_bounds();
        const double size = box.is_empty() ? 0 : std::hypot(box.width(), box.height());
        measures_[path].emplace(ref.path, size > 0 ? size * 1e-5 : 1);
    }
    const PathMeasure& measure = *measures_[path];
    const double offset =
        ref.start_percent ? ref.start_offset * measure.length()
        : ref.path_length ? from_path_length(ref.start_offset, measure.length(), *ref.path_length)
                          : ref.start_offset;
    for (const Cluster& c : cl) {
        const double half = c.advance * c.stretch / 2;
        double d = offset + c.pen.x + half;
        if (ref.right_side) d = measure.length() - d;
        const auto at = measure.at(d);
        if (!at) continue;
        const Vec2 t = ref.right_side ? -at->tangent : at->tangent;
        const Affine m = Affine::translate(at->point.to_vec()) * Affine{t.x, t.y, -t.y, t.x, 0, 0} *
                         Affine::translate({-half, c.pen.y});
        place(glyphs, c, m);
        pen_ = m * Point{2 * half, -c.pen.y};
    }
}

// The glyphs and decorations of a cluster whose pen point `at` maps to user space.
void Layouter::place(const std::vector<LaidGlyph>& glyphs, const Cluster& c, const Affine& at) {
    const double deg = c_.chars[c.begin].rotate.value_or(0);
    const Affine turn = Affine::rotate(deg * std::numbers::pi / 180);
    const bool vert = vertical(c.begin);
    const double base = baseline(c.span);
    const double k = unit(c.span);
    const FontMetrics m = primary_[c.span] ? primary_[c.span]->metrics() : FontMetrics{};
    // The cluster's own frame: its origin on its baseline, along the line.
    // In vertical text a turned glyph's baseline runs down the line's middle,
    // and so do the decorations of every glyph, upright ones too.
    const Affine along = vert ? at * turn * Affine::rotate(std::numbers::pi / 2) *
                                    Affine::translate({0, (m.ascender + m.descender) / 2 * k})
                              : at * turn * Affine::translate({0, base});
    const Affine frame = vert && c.upright ? at * turn * Affine::translate({0, base}) : along;
    double x = 0, y = 0; // the pen within the cluster: across, and down for upright glyphs
    for (std::size_t i = c.g0; i < c.g1; ++i) {
        const LaidGlyph& g = glyphs[i];
        Affine place = frame * Affine::translate({x, 0}) * Affine::scale(c.stretch, 1);
        if (c.upright && g.font) { // upright in vertical text: its vertical origin on the pen
            const Vec2 o = g.font->vertical_origin(g.glyph) * g.scale;
            place = at * turn * Affine::translate({-o.x, y + o.y});
            y += g.font->vertical_advance(g.glyph) * g.scale;
        }
        out_.glyphs.push_back({g, place});
        x += g.advance.x * c.stretch;
    }
    for (const std::uint32_t owner : c_.spans[c.span].decorations) {
        const TextDecorationLines& d = c_.spans[owner].props.decoration;
        const double ko = unit(owner);
        const FontMetrics mo = primary_[owner] ? primary_[owner]->metrics() : FontMetrics{};
        const double width = c.advance * c.stretch + c.extra;
        if (d.underline)
            decorate(
                {owner, 0, width, -mo.underline_position * ko, mo.underline_thickness * ko, along});
        if (d.overline)
            decorate({owner, 1, width, -mo.ascender * ko, mo.underline_thickness * ko, along});
        if (d.line_through)
            decorate(
                {owner, 2, width, -mo.strikeout_position * ko, mo.strikeout_thickness * ko, along});
    }
}

// A piece that continues the last one of its decoration line (the same
// direction, height and thickness, starting where that one ends) extends
// it: a line under n characters is one rectangle, not n.
void Layouter::decorate(const DecorationPiece& d) {
    const std::pair<std::uint32_t, int> key{d.owner, d.line};
    if (const auto it = last_piece_.find(key); it != last_piece_.end()) {
        DecorationPiece& last = out_.decorations[it->second];
        const Affine& a = last.transform;
        const Affine& b = d.transform;
        const Point end = a * Point{last.width, 0};
        const Point start = b * Point{0, 0};
        const bool same_frame = a.a == b.a && a.b == b.b && a.c == b.c && a.d == b.d;
        if (same_frame && last.y == d.y && last.thickness == d.thickness &&
            distance(end, start) <= 1e-9 * (1 + std::abs(end.x) + std::abs(end.y))) {
            last.width += d.width;
            return;
        }
    }
    last_piece_[key] = out_.decorations.size();
    out_.decorations.push_back(d);
}

} // namespace

TextLayout layout_text(FontDatabase& fonts, const TextContent& content) {
    return Layouter(fonts, content).run();
}

} // namespace casteljau::svg_detail
