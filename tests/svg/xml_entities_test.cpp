// Internal entities (svg/xml_entities.h): expanded where XML expands them,
// nowhere else, and refused where expanding them would be unsafe.
#include "casteljau/render/renderer.h"
#include "casteljau/svg/reader.h"
#include "casteljau/svg/xml_entities.h"

#include <gtest/gtest.h>
#include <string>
#include <variant>

namespace casteljau {
namespace {

constexpr std::size_t kLimit = 1 << 20;

std::string expanded(const std::string& doc) {
    const EntityExpansion e = expand_entities(doc, kLimit);
    EXPECT_EQ(e.error, "") << doc;
    return e.changed ? e.text : doc;
}

// The DOCTYPE Adobe Illustrator writes (its namespaces as entities, an
// internal subset after a public ID), which was refused as a whole: the
// file is drawn, the entities in its attributes expanded.
TEST(XmlEntities, AnIllustratorFileIsDrawn) {
    const SvgResult r = parse_svg(R"(<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd" [
	<!ENTITY ns_ai "http://ns.adobe.com/AdobeIllustrator/10.0/">
	<!ENTITY ns_svg "http://www.w3.org/2000/svg">
	<!ENTITY red "#ff0000">
]>
<svg xmlns:i="&ns_ai;" xmlns="&ns_svg;" width="20" height="20">
<switch><foreignObject requiredExtensions="&ns_ai;" width="1" height="1"/>
<g i:extraneous="self"><rect width="10" height="10" fill="&red;"/><rect x="12" width="-1"/></g>
</switch></svg>)",
                                  "ai.svg");
    ASSERT_TRUE(r.scene) << r.error;
    Canvas c(20, 20);
    Renderer().render(*r.scene, Affine::identity(), c, RenderOptions{});
    EXPECT_EQ(c.row(5)[5].r, 1.0f);
    EXPECT_EQ(c.row(5)[5].g, 0.0f);
    // Lines keep their numbers: the warning names the rect's own line.
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].line, 9) << r.warnings[0].text();
}

TEST(XmlEntities, ExpandedInContentAndAttributesNestedAndNowhereElse) {
    const std::string doctype = "<!DOCTYPE svg [<!ENTITY b 'B'> <!ENTITY a \"A&b;A\">"
                                "<!-- <!ENTITY c 'no'> --> <!ENTITY b 'second'>"
                                "<!ENTITY % p 'param'> <!ATTLIST svg x CDATA '>]'>]>";
    EXPECT_EQ(expanded(doctype + "<svg x='&a;'>&b;<!-- &a; --><![CDATA[&a;]]><?pi &a;?>"
                                 "&amp;&#65;&c;&undeclared;%p;&a</svg>"),
              doctype + "<svg x='ABA'>B<!-- &a; --><![CDATA[&a;]]><?pi &a;?>"
                        "&amp;&#65;&c;&undeclared;%p;&a</svg>");
    // No entity, or none referred to: the document as it is.
    for (const std::string& doc : {std::string("<svg/>"), doctype + "<svg/>",
                                   std::string("<!DOCTYPE svg PUBLIC 'x' 'y'><svg>&a;</svg>")})
        EXPECT_FALSE(expand_entities(doc, kLimit).changed) << doc;
}

// XML 1.0, 4.4.5 and 4.5: a replacement text is data in an attribute value
// (its quotes do not end the value); character references in a literal
// value are replaced when it is declared; the predefined entities keep
// their meaning when declared again (4.6's own form of it).
TEST(XmlEntities, AttributeValuesCharacterReferencesAndThePredefinedFive) {
    const std::string dt = "<!DOCTYPE svg [<!ENTITY q '\"&lt;'><!ENTITY lt \"&#38;#60;\">"
                           "<!ENTITY e 'caf&#xE9;&#38;'><!ENTITY bad '&#xD800;&#0;&#x;'>]>";
    EXPECT_EQ(expanded(dt + "<svg id=\"&q;\" t='&q;'>&e;&lt;&bad;</svg>"),
              dt + "<svg id=\"&quot;&lt;\" t='&quot;&lt;'>caf\xC3\xA9&&lt;&#xD800;&#0;&#x;</svg>");
    const SvgResult r = parse_svg(dt + "<svg xmlns='http://www.w3.org/2000/svg' width='10' "
                                       "height='10'><title id='&q;'/></svg>",
                                  "q.svg");
    EXPECT_TRUE(r.scene) << r.error; // was "malformed XML": the quote ended the value
}

// A document in UTF-16 is decoded before its entities are expanded
// (svg/xml_encoding.h), so they are, as in UTF-8 (before, the file was
// refused); a malformed DOCTYPE is pugixml's to report.
TEST(XmlEntities, UTF16DocumentsHaveTheirEntitiesExpanded) {
    const std::string utf8 = "<!DOCTYPE svg [<!ENTITY st0 'fill:#0F0;'>]><svg xmlns="
                             "'http://www.w3.org/2000/svg' width='9' height='9'><rect width='5' "
                             "height='5' style='&st0;'/></svg>";
    std::string utf16 = "\xFF\xFE"; // little-endian, with its byte order mark
    for (const char c : utf8) utf16 += std::string{c, '\0'};
    const SvgResult r = parse_svg(utf16, "u.svg");
    ASSERT_TRUE(r.scene) << r.error;
    const Shape& s = std::get<Shape>(r.scene->root.children.at(0).item);
    ASSERT_TRUE(s.fill);
    EXPECT_EQ(s.fill->color, (Rgba{0, 1, 0, 1}));
    EXPECT_TRUE(parse_svg(utf8, "u.svg").scene);
    const SvgResult broken = parse_svg("<!DOCTYPE svg [<!ENTITY a \"&a;\"><svg/>", "b.svg");
    EXPECT_NE(broken.error.find("malformed XML"), std::string::npos) << broken.error;
}

TEST(XmlEntities, BombsCyclesAndExternalEntitiesAreRefused) {
    // "Billion laughs": 10^10 bytes, stopped at the limit, at the reference.
    std::string bomb = "<!DOCTYPE svg [\n<!ENTITY a0 \"aaaaaaaaaa\">\n";
    for (int i = 1; i < 10; ++i) {
        bomb += "<!ENTITY a" + std::to_string(i) + " \"";
        for (int k = 0; k < 10; ++k) bomb += "&a" + std::to_string(i - 1) + ";";
        bomb += "\">\n";
    }
    bomb += "]>\n<svg width='10' height='10'>\n<title>&a9;</title></svg>";
    const std::pair<std::string, std::string> cases[] = {
        {bomb, "bomb.svg:14: entity references add more than 1048576 bytes (the limit)"},
        {"<!DOCTYPE svg [<!ENTITY ext SYSTEM \"file:///etc/passwd\">]>\n"
         "<svg width='10' height='10'><title>&ext;</title></svg>",
         "bomb.svg:2: entity 'ext' is external (SYSTEM or PUBLIC), and external entities are "
         "not read"},
        {"<!DOCTYPE svg [<!ENTITY a '&b;'><!ENTITY b 'x&a;'>]><svg>&a;</svg>",
         "bomb.svg:1: entity 'a' refers to itself"}};
    SvgOptions small; // the default's 16 MiB would take the sanitized build seconds
    small.max_entity_bytes = kLimit;
    for (const auto& [text, expect] : cases) {
        const SvgResult r = parse_svg(text, "bomb.svg", small);
        EXPECT_FALSE(r.scene);
        EXPECT_EQ(r.error, expect);
    }
    std::string deep = "<!DOCTYPE svg [<!ENTITY e0 'x'>";
    for (int i = 1; i <= kMaxEntityNesting + 1; ++i)
        deep += "<!ENTITY e" + std::to_string(i) + " '&e" + std::to_string(i - 1) + ";'>";
    deep += "]><svg>&e" + std::to_string(kMaxEntityNesting + 1) + ";</svg>";
    EXPECT_NE(expand_entities(deep, kLimit).error.find("nested deeper than"), std::string::npos);
}

} // namespace
} // namespace casteljau
