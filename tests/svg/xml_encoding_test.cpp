// A document's encoding (svg/xml_encoding.h): decoded to UTF-8 as browsers
// decode it, before anything reads the text.
#include "casteljau/render/renderer.h"
#include "casteljau/svg/reader.h"
#include "casteljau/svg/xml_encoding.h"
#include "pixels.h"

#include <gtest/gtest.h>
#include <string>

namespace casteljau {
namespace {

std::string declared(const char* encoding, const std::string& body) {
    return std::string("<?xml version=\"1.0\" encoding=\"") + encoding + "\"?>\n" + body;
}

// "Привет" in windows-1251, "日本語" in Shift_JIS: what an old editor saved.
const std::string kCp1251 = "\xCF\xF0\xE8\xE2\xE5\xF2";
const std::string kShiftJis = "\x93\xFA\x96\x7B\x8C\xEA";

TEST(XmlEncoding, DeclaredEncodingsAreDecodedAndTheDeclarationSaysUtf8) {
    const DecodedDocument cyr = decode_document(declared("windows-1251", kCp1251 + "\n<a/>"));
    ASSERT_TRUE(cyr.changed) << cyr.warning;
    EXPECT_EQ(cyr.text, declared("UTF-8", "Привет\n<a/>")) << "the same lines";
    const DecodedDocument jis = decode_document(declared("Shift_JIS", kShiftJis));
    EXPECT_EQ(jis.text, declared("UTF-8", "日本語"));
    const DecodedDocument iso2022 = decode_document(declared("ISO-2022-JP", "\x1B$BF|K\\8l\x1B(B"));
    EXPECT_EQ(iso2022.text, declared("UTF-8", "日本語")) << "7-bit, but not ASCII";
}

// Labels as browsers map them (the WHATWG Encoding Standard): ISO-8859-1
// is windows-1252, whose 0x93 and 0x94 are quotation marks, not C1
// controls; its unassigned 0x81 is U+0081.
TEST(XmlEncoding, LabelsAreTheEncodingStandards) {
    const DecodedDocument d = decode_document(declared("ISO-8859-1", "\x93\xE9\x94\x81"));
    EXPECT_EQ(d.text, declared("UTF-8", "\u201C\u00E9\u201D\u0081"));
    const DecodedDocument gb = decode_document(declared("gb2312", "\xD6\xD0"));
    EXPECT_EQ(gb.text, declared("UTF-8", "中")) << "GB2312 is read as GBK";
    // GBK's 0x80 is the euro (the standard's decoder; glibc's GB18030 lacks it).
    EXPECT_EQ(decode_document(declared("GBK", "\x80\xD6\xD0")).text, declared("UTF-8", "€中"));
}

// Only the standard's labels choose a decoder: UTF-16's on a text that is
// not UTF-16 read as UTF-8 (before the review, "UCS-2" made iconv refuse
// the file as UCS-2), one the standard lacks is a warning (EBCDIC's IBM037
// made an unreadable file).
TEST(XmlEncoding, OnlyTheStandardsLabelsChooseADecoder) {
    for (const char* label : {"UCS-2", "unicode", "utf-16"}) {
        const DecodedDocument d = decode_document(declared(label, "caf\xC3\xA9"));
        EXPECT_FALSE(d.changed) << label;
        EXPECT_EQ(d.warning, "") << label;
    }
    const DecodedDocument ebcdic = decode_document(declared("IBM037", "\xC3\xA9"));
    EXPECT_FALSE(ebcdic.changed);
    EXPECT_NE(ebcdic.warning.find("'IBM037' is not known"), std::string::npos);
    EXPECT_EQ(decode_document(declared("shift-jis", kShiftJis)).text, declared("UTF-8", "日本語"));
}

// The declaration's pseudo-attributes are read in order: "encoding" within
// the version's value is not the encoding.
TEST(XmlEncoding, TheLabelIsTheEncodingPseudoAttributes) {
    EXPECT_FALSE(decode_document("<?xml version=\"encoding='windows-1251'\"?>\n\xD0\x9F").changed);
    EXPECT_FALSE(decode_document("<?xml encoding=\"windows-1251\n<svg>\xCF</svg>").changed)
        << "an unclosed value";
    EXPECT_TRUE(
        decode_document("<?xml version='1.0'  encoding = 'windows-1251' ?><a>\xCF</a>").changed);
}

TEST(XmlEncoding, Utf8AndPlainAsciiAreLeftAsTheyAre) {
    for (const std::string& doc :
         {std::string("<svg/>"), declared("UTF-8", "Привет"), declared("utf8", "<svg/>"),
          declared("windows-1251", "<svg/>"), std::string("\xEF\xBB\xBF<svg/>")})
        EXPECT_FALSE(decode_document(doc).changed) << doc;
}

// UTF-16 and UTF-32, with a byte order mark or without (appendix F).
TEST(XmlEncoding, WideEncodingsAreFoundByTheirFirstBytes) {
    const std::string text = declared("UTF-16", "<svg/>");
    std::string le = "\xFF\xFE", be = "\xFE\xFF", bare, wide("\xFF\xFE\0\0", 4);
    for (const char c : text) {
        le += std::string{c, '\0'}, be += std::string{'\0', c}, bare += std::string{c, '\0'};
        wide += std::string{c, '\0', '\0', '\0'};
    }
    for (const std::string& doc : {le, be, bare, wide})
        EXPECT_EQ(decode_document(doc).text, declared("UTF-8", "<svg/>"));
    // Without a declaration or a mark: '<' and a character, as pugixml finds it.
    std::string svg_le, svg_be;
    for (const char c : std::string("<svg/>"))
        svg_le += std::string{c, '\0'}, svg_be += std::string{'\0', c};
    EXPECT_EQ(decode_document(svg_le).text, "<svg/>");
    EXPECT_EQ(decode_document(svg_be).text, "<svg/>");
}

// A byte sequence the encoding lacks is U+FFFD, and the rest is read on.
TEST(XmlEncoding, InvalidSequencesBecomeReplacementCharacters) {
    // ("\xFF" "b": a hexadecimal escape ends where the literal does.)
    const DecodedDocument d = decode_document(declared("Shift_JIS", "a\xFF"
                                                                    "b\x81"));
    EXPECT_EQ(d.text, declared("UTF-8", "a\uFFFDb\uFFFD"));
}

// (A text of ASCII alone reads the same whatever the label, and is no warning.)
TEST(XmlEncoding, AnUnknownEncodingIsAWarningAndTheTextIsReadAsItIs) {
    const DecodedDocument d = decode_document(declared("x-martian", "\xE9"));
    EXPECT_FALSE(d.changed);
    EXPECT_EQ(d.warning, "encoding 'x-martian' is not known: the text is read as UTF-8");
    const SvgResult r = parse_svg(
        declared("x-martian",
                 "<svg xmlns='http://www.w3.org/2000/svg' width='2' height='2'><!--\xE9--></svg>"),
        "m.svg");
    ASSERT_TRUE(r.scene) << r.error;
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].text(), "m.svg:1: <?xml>: " + d.warning);
}

// The worst case, a U+FFFD (3 bytes) for every byte, outgrows the first
// buffer (1.5 bytes a byte), which grows, and nothing is lost; the
// declaration keeps its lines.
TEST(XmlEncoding, TheWorstCaseGrowsTheBufferAndKeepsEveryLine) {
    const DecodedDocument d = decode_document("<?xml version='1.0'\n encoding='Shift_JIS'?>\n" +
                                              std::string(1000, '\xFF'));
    std::string fffd;
    for (int i = 0; i < 1000; ++i) fffd += "\uFFFD";
    EXPECT_EQ(d.text, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\n" + fffd);
}

// What a user sees: text saved in windows-1251 draws as the same text saved
// in UTF-8 (before, a box for every letter); a UTF-16 file's xml-stylesheet
// link is read.
TEST(XmlEncoding, DocumentsDrawAsTheirUtf8Twins) {
    const auto draw = [](const std::string& doc) {
        const SvgResult r = parse_svg(doc, "t.svg");
        EXPECT_TRUE(r.scene) << r.error;
        EXPECT_TRUE(r.warnings.empty()) << r.warnings.at(0).text();
        Canvas c(120, 40);
        if (r.scene) Renderer().render(*r.scene, Affine::identity(), c, RenderOptions{});
        return c;
    };
    const std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' width='120' height='40'>"
                            "<text x='4' y='30' font-size='24'>%</text></svg>";
    const auto with = [&](const std::string& s) {
        std::string t = svg;
        return t.replace(t.find('%'), 1, s);
    };
    const Canvas utf8 = draw(with("Привет"));
    double ink = 0;
    for (int y = 0; y < utf8.height(); ++y)
        for (int x = 0; x < utf8.width(); ++x) ink += utf8.row(y)[x].a;
    EXPECT_GT(ink, 50.0) << "the text is drawn";
    EXPECT_EQ(testing::max_difference(draw(declared("windows-1251", with(kCp1251))), utf8), 0.0f);
    std::string utf16 = "\xFF\xFE";
    for (const char c : "<?xml-stylesheet href=\"data:text/css,rect{fill:%23f00}\"?><svg "
                        "xmlns='http://www.w3.org/2000/svg' width='4' height='4'><rect "
                        "width='4' height='4'/></svg>")
        if (c) utf16 += std::string{c, '\0'};
    const Canvas linked = draw(utf16);
    EXPECT_EQ(linked.row(2)[2].r, 1.0f) << "the linked sheet applies";
}

} // namespace
} // namespace casteljau
