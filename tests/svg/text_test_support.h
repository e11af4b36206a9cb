// Shared by the SVG text tests (text_test.cpp: reading; text_layout_test.cpp:
// layout): a font database of the pinned fonts only (DejaVu and Noto), a
// document read with it, the shapes it draws and their bounds, and the text
// library's own line, advance and metrics to compare with.
#pragma once

#include "casteljau/svg/reader.h"
#include "casteljau/text/font_database.h"
#include "casteljau/text/layout.h"

#include <cstdint>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

namespace casteljau::svg_text_test {

// The fonts every test sets text in: only the pinned folders.
inline FontDatabase& fonts() {
    static const std::unique_ptr<FontDatabase> db = [] {
        auto d = FontDatabase::empty();
        d->add_font_dir("/usr/share/fonts/truetype/dejavu");
        d->add_font_dir("/usr/share/fonts/truetype/noto");
        return d;
    }();
    return *db;
}

inline SvgResult read(const std::string& body, SvgOptions o = {}) {
    o.fonts = &fonts();
    return parse_svg(
        R"svg(<svg xmlns="http://www.w3.org/2000/svg" )svg"
        R"svg(xmlns:xlink="http://www.w3.org/1999/xlink" width="400" height="200">)svg" +
            body + "</svg>",
        "t.svg", o);
}

// Every shape of the scene in drawing order.
inline void collect(const Group& g, std::vector<const Shape*>& out) {
    for (const Node& n : g.children) {
        if (const Shape* s = std::get_if<Shape>(&n.item))
            out.push_back(s);
        else
            collect(std::get<Group>(n.item), out);
    }
}
inline std::vector<const Shape*> shapes(const SvgResult& r) {
    std::vector<const Shape*> out;
    if (r.scene) collect(r.scene->root, out);
    return out;
}

// The union of the shapes' path bounds (user space; the tests use no transform).
inline Rect bounds(const std::vector<const Shape*>& s) {
    Rect b = Rect::empty();
    for (const Shape* x : s) b = b.united(x->path.bounds());
    return b;
}

// The bounds of a text read from `body`, all its shapes together.
inline Rect bounds_of(const std::string& body) {
    const SvgResult r = read(body);
    EXPECT_TRUE(r.scene) << r.error;
    return bounds(shapes(r));
}

inline std::string str(const Rect& r) {
    std::ostringstream s;
    s << '[' << r.x0 << ", " << r.y0 << ", " << r.x1 << ", " << r.y1 << ']';
    return s.str();
}

inline void expect_rect(const Rect& got, const Rect& want, double tol, const std::string& what) {
    EXPECT_NEAR(got.x0, want.x0, tol) << what << ": got " << str(got) << ", want " << str(want);
    EXPECT_NEAR(got.y0, want.y0, tol) << what << ": got " << str(got) << ", want " << str(want);
    EXPECT_NEAR(got.x1, want.x1, tol) << what << ": got " << str(got) << ", want " << str(want);
    EXPECT_NEAR(got.y1, want.y1, tol) << what << ": got " << str(got) << ", want " << str(want);
}

inline Rect moved(const Rect& r, double dx, double dy) {
    return {r.x0 + dx, r.y0 + dy, r.x1 + dx, r.y1 + dy};
}

inline constexpr const char* kDejaVu = "DejaVu Sans";

inline TextStyle style(double size, const char* family = kDejaVu) {
    TextStyle s;
    s.font.families = {family};
    s.size = size;
    return s;
}

// The ink of a line of text set by the text library, its baseline's start at `at`.
inline Rect ink(const std::string& utf8, const TextStyle& s, Point at = {},
                TextDirection dir = TextDirection::Ltr) {
    return text_to_path(fonts(), utf8, s, at, dir).bounds();
}
inline double advance(const std::string& utf8, const TextStyle& s) {
    return text_advance(fonts(), utf8, s);
}
// The space left of a character's ink and right of it, px.
inline double left_bearing(const std::string& c, const TextStyle& s) { return ink(c, s).x0; }
inline double right_bearing(const std::string& c, const TextStyle& s) {
    return advance(c, s) - ink(c, s).x1;
}

inline FontMetrics metrics(const char* family = kDejaVu) {
    FontQuery q;
    q.families = {family};
    const auto face = fonts().match(q);
    EXPECT_TRUE(face);
    const auto font = face ? fonts().font(*face) : nullptr;
    EXPECT_TRUE(font);
    return font ? font->metrics() : FontMetrics{};
}

// A few values read straight from a font file's tables (OpenType spec), to
// check the library's metrics against: 0 when the table is missing.
struct SfntValues {
    double units_per_em = 0;                                // head
    double underline_position = 0, underline_thickness = 0; // post: the top of the stroke
    double strikeout_size = 0, strikeout_position = 0;      // OS/2: the top of the stroke
    double x_height = 0, cap_height = 0;                    // OS/2 version 2 and later
};

inline SfntValues read_sfnt(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    const std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto u16 = [&](std::size_t at) {
        return at + 2 <= b.size() ? unsigned(std::uint8_t(b[at])) << 8 | std::uint8_t(b[at + 1])
                                  : 0u;
    };
    const auto i16 = [&](std::size_t at) { return double(std::int16_t(std::uint16_t(u16(at)))); };
    const auto u32 = [&](std::size_t at) { return std::size_t(u16(at)) << 16 | u16(at + 2); };
    SfntValues v;
    const std::size_t tables = u16(4);
    for (std::size_t t = 0; t < tables; ++t) {
        const std::size_t rec = 12 + 16 * t;
        if (rec + 16 > b.size()) break;
        const std::string tag = b.substr(rec, 4);
        const std::size_t at = u32(rec + 8);
        if (tag == "head") v.units_per_em = u16(at + 18);
        if (tag == "post") v.underline_position = i16(at + 8), v.underline_thickness = i16(at + 10);
        if (tag == "OS/2") {
            v.strikeout_size = i16(at + 26);
            v.strikeout_position = i16(at + 28);
            if (u16(at) >= 2) v.x_height = i16(at + 86), v.cap_height = i16(at + 88);
        }
    }
    return v;
}

inline constexpr const char* kDejaVuFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
inline constexpr const char* kNotoFile = "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf";

inline std::string text(const std::string& attrs, const std::string& content) {
    return R"svg(<text font-family="DejaVu Sans" )svg" + attrs + ">" + content + "</text>";
}

// Three characters, each in a tspan of its own (a Shape each).
inline std::string each(const std::vector<std::string>& chars, const std::string& attrs = "") {
    std::string out;
    for (const std::string& c : chars) out += "<tspan" + attrs + ">" + c + "</tspan>";
    return out;
}

} // namespace casteljau::svg_text_test
