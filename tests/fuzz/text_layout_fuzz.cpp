// Fuzz target: text layout. The first bytes choose the attributes of a
// <text> and of the tspan, textPath and tref inside it (font-family from a
// short list, font-size, letter- and word-spacing, direction, writing-mode,
// text-anchor, baselines, decorations, x, dx, dy and rotate lists,
// textLength), numbers now and then hostile (1e300, nan, 1e-300); the rest
// is its text, raw bytes taken as UTF-8 (so possibly not UTF-8), cut into
// the elements' pieces at each 0 byte. The document is read and rendered
// scaled down to 96 x 96 px, as svg_render does, and the whole text is also
// set as one line through the library's API (text_to_path, text_advance).
//
// Fonts are the test suite's (tests/text/fonts.conf, which the build names
// in CASTELJAU_TEST_FONTS_CONF) unless FONTCONFIG_FILE names others: the
// same fonts on every machine, and none of the system configuration's files,
// whose reading leaks in fontconfig 2.14 (LeakSanitizer reports it at exit).
// Reading and markup escapes are not at stake here (svg_read fuzzes those):
// the bytes go in escaped where XML would take them as markup.
#include "casteljau/svg/reader.h"
#include "casteljau/text/layout.h"
#include "fuzz_input.h"
#include "fuzz_target.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace casteljau;

using fuzz::Bytes;

FontDatabase& fonts() {
    static FontDatabase& db = []() -> FontDatabase& {
#ifdef CASTELJAU_TEST_FONTS_CONF
        setenv("FONTCONFIG_FILE", CASTELJAU_TEST_FONTS_CONF, 0);
#endif
        return FontDatabase::system();
    }();
    return db;
}

std::string num(double v) {
    if (std::isnan(v)) return "nan";
    char s[32];
    std::snprintf(s, sizeof s, "%.17g", v);
    return s;
}

std::string list(Bytes& b) {
    std::string s;
    for (int i = b.byte() % 9; i > 0; --i) s += num(b.number()) + (i > 1 ? " " : "");
    return s;
}

const char* const kFamilies[] = {
    "serif",        "sans-serif",          "monospace", "cursive",
    "system-ui",    "DejaVu Sans",         "Noto Sans", "DejaVu Sans Mono, serif",
    "no such font", "'Noto Serif', emoji", ""};
const char* const kDirections[] = {"ltr", "rtl"};
const char* const kWritingModes[] = {"horizontal-tb", "vertical-rl", "vertical-lr", "tb", "lr"};
const char* const kAnchors[] = {"start", "middle", "end"};
const char* const kBaselines[] = {"auto",         "alphabetic",       "central",
                                  "middle",       "hanging",          "ideographic",
                                  "mathematical", "text-before-edge", "text-after-edge"};
const char* const kShifts[] = {"sub", "super", "baseline", "3", "-50%", "1e300"};
const char* const kDecorations[] = {"underline", "overline", "line-through",
                                    "underline overline line-through", "none"};
const char* const kBidi[] = {"normal",           "embed",    "isolate", "bidi-override",
                             "isolate-override", "plaintext"};
const char* const kSpaces[] = {"default", "preserve"};
const char* const kAdjust[] = {"spacing", "spacingAndGlyphs"};
const char* const kPaths[] = {"M10 60 C 30 0 70 120 90 40",
                              "M10 10",
                              "M10 10 L10 10",
                              "M0 0 Z",
                              "M5 50 h1e300",
                              "M50 50 m-40 0 a40 40 0 1 0 80 0 a40 40 0 1 0 -80 0"};
const char* const kSides[] = {"left", "right"};

// The attributes of one element: three bytes say which are present (the
// bits in the order below), and each present one reads its value.
std::string attributes(Bytes& b) {
    unsigned mask = b.byte();
    mask |= unsigned(b.byte()) << 8;
    mask |= unsigned(b.byte()) << 16;
    std::string a;
    unsigned bit = 1;
    const auto put = [&](const char* name, auto value) {
        if (mask & bit) a += std::string(" ") + name + "=\"" + value() + "\"";
        bit <<= 1;
    };
    put("font-family", [&] { return std::string(b.pick(kFamilies)); });
    put("font-size", [&] { return num(b.number()); });
    put("letter-spacing", [&] { return num(b.number()); });
    put("word-spacing", [&] { return num(b.number()); });
    put("direction", [&] { return std::string(b.pick(kDirections)); });
    put("writing-mode", [&] { return std::string(b.pick(kWritingModes)); });
    put("text-anchor", [&] { return std::string(b.pick(kAnchors)); });
    put("dominant-baseline", [&] { return std::string(b.pick(kBaselines)); });
    put("baseline-shift", [&] { return std::string(b.pick(kShifts)); });
    put("text-decoration", [&] { return std::string(b.pick(kDecorations)); });
    put("unicode-bidi", [&] { return std::string(b.pick(kBidi)); });
    put("xml:space", [&] { return std::string(b.pick(kSpaces)); });
    put("x", [&] { return list(b); });
    put("dx", [&] { return list(b); });
    put("dy", [&] { return list(b); });
    put("rotate", [&] { return list(b); });
    put("textLength", [&] { return num(b.number()); });
    put("lengthAdjust", [&] { return std::string(b.pick(kAdjust)); });
    put("y", [&] { return list(b); });
    put("font-weight", [&] { return num(b.byte() * 4); });
    return a;
}

// Text bytes as element content: markup characters escaped, NUL (which
// ends an XML string) dropped, the rest as is.
std::string content(std::string_view s) {
    std::string out;
    for (const char c : s) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else if (c != '\0')
            out += c;
    }
    return out;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FontDatabase& db = fonts(); // before the reader takes FontDatabase::system()
    Bytes b{data, size, true};
    const unsigned structure = b.byte();
    const std::string text_attrs = attributes(b);
    const std::string span_attrs = attributes(b);
    const std::string inner_attrs = attributes(b);
    const std::string path_attrs = attributes(b);
    const std::string path_d = b.pick(kPaths);
    const std::string start_offset = (b.byte() & 1) ? num(b.number()) : num(b.number()) + "%";
    const std::string side = b.pick(kSides);
    // The text: what is left, cut at each 0 byte into up to five pieces.
    const std::string_view all(reinterpret_cast<const char*>(b.p), b.n);
    std::string_view piece[5];
    std::size_t from = 0;
    for (int i = 0; i < 5 && from <= all.size(); ++i) {
        const std::size_t to = i == 4 ? all.size() : std::min(all.find('\0', from), all.size());
        piece[i] = all.substr(from, to - from);
        from = to + 1;
    }
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100\" height=\"100\">\n";
    svg += "<path id=\"p\" d=\"" + path_d + "\" fill=\"none\"/>\n";
    svg += "<g transform=\"translate(0 50)\"><text id=\"t\"" + text_attrs + ">" + content(piece[0]);
    if (structure & 1) {
        svg += "<tspan" + span_attrs + ">" + content(piece[1]);
        if (structure & 2) svg += "<tspan" + inner_attrs + ">" + content(piece[2]) + "</tspan>";
        svg += "</tspan>";
    }
    if (structure & 4) {
        svg += "<textPath href=\"#p\" startOffset=\"" + start_offset + "\" side=\"" + side + "\"" +
               path_attrs + ">" + content(piece[3]);
        if (structure & 8) svg += "<tspan" + inner_attrs + ">" + content(piece[2]) + "</tspan>";
        svg += "</textPath>";
    }
    if (structure & 16) svg += "<tref href=\"#t\"/>";
    if (structure & 32) svg += "<a" + inner_attrs + ">" + content(piece[4]) + "</a>";
    svg += "</text></g>\n</svg>\n";

    const SvgResult r = parse_svg(svg, "fuzz.svg");
    if (r.scene) fuzz::render_small(*r.scene);

    // The same text as one line, through the library's API.
    Bytes c{data, size}; // the first bytes again, read as a style
    TextStyle style;
    style.font.families = {c.pick(kFamilies)};
    style.font.weight = 1 + c.byte() * 4;
    style.font.style = FontStyle(c.byte() % 3);
    style.font.stretch = 50 + c.byte() % 151;
    style.size = c.number();
    style.letter_spacing = c.number();
    style.word_spacing = c.number();
    if (c.byte() & 1) style.size_adjust = c.number();
    if (c.byte() & 1) style.features.push_back({{'l', 'i', 'g', 'a'}, false});
    const TextDirection dir = TextDirection(c.byte() % 3);
    const Path line = text_to_path(db, all, style, {c.number(), c.number()}, dir);
    (void)line.bounds();
    (void)text_advance(db, all, style, dir);
    return 0;
}
