// @font-face (svg/font_face.h): descriptors read as CSS Fonts 4 says, fonts
// from data: URLs and files drawn as the same font installed, sources tried
// in order, and a document's fonts kept to that document.
#include "casteljau/svg/font_face.h"
#include "text_test_support.h"

#include <gtest/gtest.h>

namespace casteljau::svg_text_test {
namespace {

const std::string kSerifBold = "/usr/share/fonts/truetype/dejavu/DejaVuSerif-Bold.ttf";

std::string base64(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    static constexpr char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= std::uint8_t(bytes[i + 2]);
        out += kDigits[v >> 18 & 63];
        out += kDigits[v >> 12 & 63];
        out += i + 1 < bytes.size() ? kDigits[v >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
    }
    return out;
}

std::vector<CssDeclaration> declarations(const std::string& block) {
    std::vector<CssProblem> problems;
    auto d = parse_css_declarations(block, problems);
    EXPECT_TRUE(problems.empty()) << problems.front().message;
    return d;
}

TEST(FontFace, DescriptorsAsCssFonts4) {
    std::string error;
    auto r = parse_font_face(declarations(R"css(font-family: "My Font";
        src: local(Foo), url("a b.woff2") format("woff2"), url(c.ttf) format(TrueType) tech(variations),
             url(d.eot) format("embedded-opentype"), bogus(1), url(e.otf);
        font-weight: 800 300; font-style: oblique 10deg; font-display: swap)css"),
                             error);
    ASSERT_TRUE(r) << error;
    EXPECT_EQ(r->descriptors.family, "My Font");
    EXPECT_EQ(r->descriptors.weight_min, 300);
    EXPECT_EQ(r->descriptors.weight_max, 800);
    EXPECT_EQ(r->descriptors.style, FontStyle::Oblique);
    ASSERT_EQ(r->sources.size(), 4u);
    EXPECT_EQ(r->sources[0].url, "a b.woff2");
    EXPECT_EQ(r->sources[0].format, "woff2");
    EXPECT_EQ(r->sources[1].url, "c.ttf");
    EXPECT_EQ(r->sources[1].format, "truetype");
    EXPECT_FALSE(readable_font_format(r->sources[2].format));
    EXPECT_EQ(r->sources[3].url, "e.otf");
    EXPECT_TRUE(r->sources[3].format.empty());
    // Bold, one weight; an invalid weight keeps the default.
    r = parse_font_face(declarations("font-family: X; src: url(x); font-weight: bold"), error);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->descriptors.weight_min, 700);
    r = parse_font_face(declarations("font-family: X; src: url(x); font-weight: 1001"), error);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->descriptors.weight_max, 400);
    // Without a family or a src, or with a list of families, the rule is ignored.
    EXPECT_FALSE(parse_font_face(declarations("src: url(x)"), error));
    EXPECT_FALSE(parse_font_face(declarations("font-family: A, B; src: url(x)"), error));
    EXPECT_FALSE(parse_font_face(declarations("font-family: A; src: nonsense"), error));
    EXPECT_FALSE(error.empty());
}

// Text in an @font-face family draws the same outlines as the same font
// installed under its own name, from a data: URL and from a file.
TEST(FontFace, AFontFromADataUrlOrAFileDrawsAsInstalled) {
    const std::string text = R"svg(<text x="10" y="100" font-size="40">Hamburg</text>)svg";
    const auto installed =
        read(R"svg(<g font-family="DejaVu Serif" font-weight="bold">)svg" + text + "</g>");
    ASSERT_TRUE(installed.scene);
    const Rect want = bounds(shapes(installed));
    const auto data =
        read("<style>@font-face { font-family: Embedded; src: url(data:font/ttf;base64," +
             base64(kSerifBold) + ") format('truetype') }</style>" +
             R"svg(<g font-family="Embedded">)svg" + text + "</g>");
    ASSERT_TRUE(data.scene);
    EXPECT_TRUE(data.warnings.empty()) << data.warnings.front().text();
    expect_rect(bounds(shapes(data)), want, 1e-9, "data: URL");
    SvgOptions o;
    o.base_dir = "/usr/share/fonts/truetype/dejavu";
    // The first sources fail (no such file; a format FreeType does not read): the last loads.
    const auto file = read("<style>@font-face { font-family: Embedded; src: url(none.ttf), "
                           "url(DejaVuSerif-Bold.ttf) format('svg'), url(DejaVuSerif-Bold.ttf) }"
                           "</style><g font-family='Embedded'>" +
                               text + "</g>",
                           o);
    ASSERT_TRUE(file.scene);
    EXPECT_TRUE(file.warnings.empty()) << file.warnings.front().text();
    expect_rect(bounds(shapes(file)), want, 1e-9, "file");
}

// A rule that loads nothing is told once, at its line; the text takes the
// next family. The next document does not see the last one's fonts.
TEST(FontFace, AFailedRuleWarnsAndFontsStayInTheirDocument) {
    const std::string text =
        R"svg(<text x="10" y="100" font-size="40" font-family="Embedded, DejaVu Sans">Hamburg</text>)svg";
    const auto plain = read(text);
    const auto broken = read("<style>\n\n@font-face { font-family: Embedded;\n"
                             "src: url(data:font/ttf;base64,AAAA) }</style>" +
                             text);
    ASSERT_TRUE(broken.scene);
    ASSERT_EQ(broken.warnings.size(), 1u);
    EXPECT_EQ(broken.warnings[0].line, 3) << broken.warnings[0].text();
    EXPECT_NE(broken.warnings[0].text().find("no source of 'Embedded' loads"), std::string::npos)
        << broken.warnings[0].text();
    expect_rect(bounds(shapes(broken)), bounds(shapes(plain)), 1e-9, "broken");
    const auto embedded = read("<style>@font-face { font-family: Embedded; src: url(data:,"
                               "x), url(data:font/ttf;base64," +
                               base64(kSerifBold) + ") }</style>" + text);
    ASSERT_TRUE(embedded.scene);
    EXPECT_NE(str(bounds(shapes(embedded))), str(bounds(shapes(plain))));
    expect_rect(bounds(shapes(read(text))), bounds(shapes(plain)), 1e-9, "the next document");
}

} // namespace
} // namespace casteljau::svg_text_test
