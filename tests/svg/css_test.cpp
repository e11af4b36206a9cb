// CSS style sheets (svg/css.h): parsing and its error recovery (CSS Syntax
// 3), selector matching (Selectors 4) on small pugixml documents, the
// cascade order (specificity, then source order; !important flagged), the
// rule index against a brute-force matcher on random documents, the
// limits. The reader's use of them: css_properties_test.cpp.
#include "casteljau/svg/css.h"
#include "casteljau/svg/detail/css_pugi.h"
#include "casteljau/svg/reader.h"

#include <algorithm>
#include <functional>
#include <gtest/gtest.h>
#include <random>
#include <sstream>

namespace casteljau {
namespace {

using svg_detail::PugiCssTree;

struct Doc {
    pugi::xml_document xml;
    PugiCssTree tree;
    std::vector<pugi::xml_node> elements; // in document order
    explicit Doc(const char* text) {
        EXPECT_TRUE(xml.load_string(text)) << text;
        const std::function<void(pugi::xml_node)> visit = [&](pugi::xml_node n) {
            for (pugi::xml_node c : n.children())
                if (c.type() == pugi::node_element) {
                    elements.push_back(c);
                    visit(c);
                }
        };
        visit(xml);
    }
    pugi::xml_node by_id(const char* id) const {
        return xml.find_node(
            [&](pugi::xml_node n) { return n.attribute("id").value() == std::string(id); });
    }
};

// "name:value", with a '!' after important ones, in cascade order.
std::string cascade(const StyleSheet& sheet, const Doc& doc, const char* id) {
    CssMatcher m(sheet, doc.tree);
    std::vector<const CssDeclaration*> out;
    EXPECT_TRUE(m.match(PugiCssTree::node(doc.by_id(id)), out));
    std::string s;
    for (const CssDeclaration* d : out)
        s += (s.empty() ? "" : " ") + d->name + ":" + d->value + (d->important ? "!" : "");
    return s;
}

StyleSheet sheet_of(const std::string& css, std::vector<CssProblem>* problems = nullptr) {
    StyleSheet sheet;
    std::vector<CssProblem> local;
    sheet.parse(css, problems ? *problems : local);
    if (!problems)
        for (const CssProblem& p : local)
            ADD_FAILURE() << css << "\n line " << p.line << ": " << p.message;
    return sheet;
}

std::string problems_text(const std::vector<CssProblem>& problems) {
    std::string s;
    for (const CssProblem& p : problems)
        s += std::to_string(p.line) + (p.unsupported ? "u" : "") + ": " + p.message + "\n";
    return s;
}

const char* const kTree = R"(<svg id="root" xmlns:xlink="http://www.w3.org/1999/xlink">
  <g id="g1" class="layer top">
    <rect id="r1" class="a b" data-x="foo-bar" lang="en-US"/>
    <circle id="c1" class="b"/>
    <rect id="r2" data-x="bar baz"/>
    <text id="t1">hi</text>
  </g>
  <g id="g2">
    <g id="g3"><rect id="r3" class="A"/></g>
    <path id="p1"/>
  </g>
  <a id="a1" xlink:href="#r1"><rect id="r4"/></a>
  <g id="empty"/>
</svg>)";

// The ids of the elements of kTree that `selector` matches, in document order.
std::string matching(const std::string& selector) {
    static const Doc doc(kTree);
    const StyleSheet sheet = sheet_of(selector + " { m: 1 }");
    CssMatcher m(sheet, doc.tree);
    std::vector<const CssDeclaration*> out;
    std::string ids;
    for (const pugi::xml_node& n : doc.elements) {
        EXPECT_TRUE(m.match(PugiCssTree::node(n), out));
        if (out.empty()) continue;
        if (!ids.empty()) ids += ' ';
        ids += n.attribute("id").value();
    }
    return ids;
}

TEST(CssParse, DeclarationsNamesAndImportant) {
    std::vector<CssProblem> problems;
    const auto d = parse_css_declarations(
        "fill: red; stroke : blue !important;STROKE-Width:2!IMPORTANT;--My-Var: x ;;"
        "opacity: .5 ! /* c */ important",
        problems);
    EXPECT_TRUE(problems.empty()) << problems_text(problems);
    ASSERT_EQ(d.size(), 5u);
    EXPECT_EQ(d[0].name, "fill");
    EXPECT_EQ(d[0].value, "red");
    EXPECT_FALSE(d[0].important);
    EXPECT_EQ(d[1].value, "blue");
    EXPECT_TRUE(d[1].important);
    EXPECT_EQ(d[2].name, "stroke-width"); // property names are case-insensitive
    EXPECT_EQ(d[2].value, "2");
    EXPECT_TRUE(d[2].important);
    EXPECT_EQ(d[3].name, "--My-Var"); // custom properties are not
    EXPECT_EQ(d[3].value, "x");
    EXPECT_EQ(d[4].value, ".5");
    EXPECT_TRUE(d[4].important);
}

TEST(CssParse, CommentsStringsAndEscapes) {
    std::vector<CssProblem> problems;
    const auto d = parse_css_declarations(
        "fill:/* a; b */red/**/;stroke: rgb(1,/*x*/2,  3) ; font-family: \"a;b\\\"c\", 'd}e';"
        "color: \\72 ed; marker: url(a;b) ; x: 10/**/px",
        problems);
    EXPECT_TRUE(problems.empty()) << problems_text(problems);
    ASSERT_EQ(d.size(), 6u);
    EXPECT_EQ(d[0].value, "red");
    EXPECT_EQ(d[1].value, "rgb(1, 2, 3)");
    EXPECT_EQ(d[2].value, "\"a;b\\\"c\", 'd}e'"); // strings keep their source text
    EXPECT_EQ(d[3].value, "red");                 // an escape spelling an identifier
    EXPECT_EQ(d[4].value, "url(a;b)");            // an unquoted url is one token
    EXPECT_EQ(d[5].value, "10 px");               // a comment separates tokens
    // Escapes in selectors: hex with the space that ends it, a quote in a string.
    EXPECT_EQ(matching(".\\61  "), "r1");
    EXPECT_EQ(matching("#\\72 1"), "r1");
    EXPECT_EQ(matching("#r\\31"), "r1");
    EXPECT_EQ(matching("[data-x=\"foo\\-bar\"]"), "r1");
    EXPECT_EQ(matching("[data-x='b\\61r baz']"), "r2");
    EXPECT_EQ(matching("/* g */ rect/**/#r2 /* */"), "r2");
}

TEST(CssParse, AtRulesAreSkippedWhole) {
    std::vector<CssProblem> problems;
    const StyleSheet sheet = sheet_of(R"(@charset "utf-8";
@import url("other.css") screen;
@media (min-width: 1px) { rect { fill: red } g { x: y } }
@font-face { font-family: x; src: url(a.woff) }
@supports (display: grid) and (not (x: y)) { @media print { rect { fill: red } } }
@keyframes k { from { opacity: 0 } to { opacity: 1 } }
@unknown-thing foo bar;
<!-- rect { fill: green } -->
)",
                                      &problems);
    const Doc doc(kTree);
    EXPECT_EQ(cascade(sheet, doc, "r1"), "fill:green");
    // Not @charset, nor @import at the head (css_imports'), nor @font-face,
    // which is kept for the reader (svg/font_face.h).
    ASSERT_EQ(problems.size(), 4u) << problems_text(problems);
    for (std::size_t i = 0; i < problems.size(); ++i) {
        EXPECT_TRUE(problems[i].unsupported) << problems_text(problems);
        EXPECT_EQ(problems[i].line, int(i) + (i < 1 ? 3 : 4)) << problems_text(problems);
    }
    ASSERT_EQ(sheet.font_faces().size(), 1u);
    EXPECT_EQ(sheet.font_faces()[0].line, 4);
    ASSERT_EQ(sheet.font_faces()[0].descriptors.size(), 2u);
    EXPECT_EQ(sheet.font_faces()[0].descriptors[1].value, "url(a.woff)");
}

TEST(CssParse, ImportsAreTheSheetsHeadAndAreListedNotRead) {
    const char* css = R"(@charset "utf-8"; <!--
@import url("a.css");
@import 'b\2e css' screen and (min-width: 10px);
@import url(c.css)print;
@import 12;
@import url("d.css") layer(base);
rect { fill: red }
@import "late.css";
@media print { @import "nested.css"; }
)";
    std::vector<CssProblem> problems;
    const std::vector<CssImport> imports = css_imports(css, problems);
    ASSERT_EQ(imports.size(), 3u);
    EXPECT_EQ(imports[0].url, "a.css");
    EXPECT_EQ(imports[0].media, "");
    EXPECT_EQ(imports[0].line, 2);
    EXPECT_EQ(imports[1].url, "b.css");
    EXPECT_EQ(imports[1].media, "screen and (min-width: 10px)");
    EXPECT_EQ(imports[2].url, "c.css");
    EXPECT_EQ(imports[2].media, "print");
    ASSERT_EQ(problems.size(), 2u) << problems_text(problems);
    EXPECT_EQ(problems[0].line, 5);
    EXPECT_FALSE(problems[0].unsupported);
    EXPECT_EQ(problems[1].line, 6);
    EXPECT_TRUE(problems[1].unsupported);
    // The parser skips the head's imports, and tells the one after a rule
    // (CSS ignores it); the one inside @media print is skipped with its block.
    problems.clear();
    StyleSheet sheet;
    sheet.parse(css, problems);
    ASSERT_EQ(problems.size(), 1u) << problems_text(problems);
    EXPECT_EQ(problems[0].line, 8);
    EXPECT_NE(problems[0].message.find("@import after other rules"), std::string::npos);
    EXPECT_EQ(sheet.size(), 1u);
}

TEST(CssParse, MediaRulesApplyAsAPictureAnswersThem) {
    // svg/media_query.h: screen, light, no unknown feature; nested @media
    // within a matching one; the rest skipped, an unknown feature reported.
    std::vector<CssProblem> problems;
    const std::string css = R"(rect { a: 0 }
@media screen { rect { a: 1 } @media (prefers-color-scheme: light) { rect { b: 1 } } }
@media (prefers-color-scheme: dark) { rect { a: 2 } }
@media print, (orientation: portrait) { rect { a: 3 } }
@media not print and (color) { rect { c: 1 } }
@media only screen and (not (monochrome)) { rect { d: 1 } }
@media (scripting: none) or (hover) { rect { e: 1 } }
circle { f: 1 })";
    const StyleSheet sheet = sheet_of(css, &problems);
    const Doc doc(kTree);
    EXPECT_EQ(cascade(sheet, doc, "r1"), "a:0 a:1 b:1 c:1 d:1");
    EXPECT_EQ(cascade(sheet, doc, "c1"), "f:1") << "the sheet goes on after the blocks";
    ASSERT_EQ(problems.size(), 2u) << problems_text(problems);
    EXPECT_TRUE(problems[0].unsupported && problems[1].unsupported);
    EXPECT_EQ(problems[0].line, 4);
    EXPECT_NE(problems[0].message.find("(orientation: portrait)"), std::string::npos);
    EXPECT_EQ(problems[1].line, 7) << "(hover) makes its query false, or or not";
    StyleSheet dark;
    std::vector<CssProblem> quiet;
    dark.parse(css, quiet, MediaContext{true});
    EXPECT_EQ(cascade(dark, doc, "r1"), "a:0 a:1 a:2 c:1 d:1");
}

TEST(MediaQuery, ListsTypesAndConditions) {
    const MediaContext light;
    for (const char* yes :
         {"", "all", "screen", "ALL", "not print", "only screen", "print, screen", "(color)",
          "(prefers-color-scheme: light)", "((color) and (grid: 0))", "not (monochrome)",
          "(forced-colors: none) and (prefers-contrast: no-preference)"})
        EXPECT_TRUE(media_matches(yes, light, nullptr)) << yes;
    for (const char* no : {"print", "not screen", "(prefers-color-scheme: dark)", "(monochrome)",
                           "screen and", "(color) and (grid) or (color)", "(color", "screen print",
                           "(width >= 10px)", "not (hover)"})
        EXPECT_FALSE(media_matches(no, light, nullptr)) << no;
    std::string unknown;
    EXPECT_FALSE(media_matches("screen and (max-width: 600px)", light, &unknown));
    EXPECT_EQ(unknown, "(max-width: 600px)");
    EXPECT_TRUE(media_matches("(prefers-color-scheme: dark)", MediaContext{true}, &unknown));
    EXPECT_EQ(unknown, "");
}

// Each sheet: one problem (at `line`), and `rect.b` / circle still styled.
TEST(CssParse, MalformedRulesAreRecoveredFrom) {
    struct Case {
        const char* css;
        int line;
        const char* c1; // what circle#c1 gets
    };
    const Case cases[] = {
        {"circle { fill red; stroke: blue }", 1, "stroke:blue"},
        {"circle { : red; stroke: blue }", 1, "stroke:blue"},
        {"circle { fill: ; stroke: blue }", 1, "stroke:blue"},
        {"circle { 12px; stroke: blue }", 1, "stroke:blue"},
        {"circle {\n fill: \"red\n; stroke: blue }", 2, "stroke:blue"},
        {"circle { fill: url(a b); stroke: blue }", 1, "stroke:blue"},
        {"#1a { fill: red }\ncircle { stroke: blue }", 1, "stroke:blue"},
        {"circle, 1rect { fill: red }\ncircle { stroke: blue }", 1, "stroke:blue"},
        {"circle:bogus { fill: red }\ncircle { stroke: blue }", 1, "stroke:blue"},
        {"circle > { fill: red }\ncircle { stroke: blue }", 1, "stroke:blue"},
        {"} circle { fill: red }\ncircle { stroke: blue }", 1, "stroke:blue"},
        {"circle; rect { fill: red }\ncircle { stroke: blue }", 1, "stroke:blue"},
        {"[data-x= { fill: red }\n circle { stroke: blue }", 1, ""}, // '[' eats the rest
        {"circle { stroke: blue", 1, "stroke:blue"},                 // kept, closed at the end
        {"circle { stroke: blue } /* unclosed", 1, "stroke:blue"},
        {"circle { stroke: blue; @media x { a: b } fill: red }", 1, "stroke:blue fill:red"},
        {"g { rect { fill: red } stroke: blue }\ncircle{stroke:blue}", 1, "stroke:blue"},
        {"circle { a:hover { fill: red } stroke: blue }", 1, "stroke:blue"},
    };
    const Doc doc(kTree);
    for (const Case& c : cases) {
        std::vector<CssProblem> problems;
        const StyleSheet sheet = sheet_of(c.css, &problems);
        ASSERT_EQ(problems.size(), 1u) << c.css << "\n" << problems_text(problems);
        EXPECT_EQ(problems[0].line, c.line) << c.css << "\n" << problems_text(problems);
        EXPECT_EQ(cascade(sheet, doc, "c1"), c.c1) << c.css;
    }
}

TEST(CssParse, CdataTextIsTheCallersToExtract) {
    // pugixml gives <![CDATA[...]]> as a cdata child; the reader passes its
    // text (with any plain text beside it), in which '>' needs no escaping.
    const Doc doc(
        R"(<svg><style><![CDATA[ g > rect { fill: red } ]]></style><g id="g"><rect id="r"/></g></svg>)");
    std::string text;
    for (const pugi::xml_node& c : doc.xml.child("svg").child("style").children())
        text += c.value();
    EXPECT_EQ(doc.xml.child("svg").child("style").first_child().type(), pugi::node_cdata);
    EXPECT_EQ(cascade(sheet_of(text), doc, "r"), "fill:red");
}

TEST(CssSelectors, TypeClassIdUniversal) {
    EXPECT_EQ(matching("rect"), "r1 r2 r3 r4");
    EXPECT_EQ(matching("RECT"), ""); // SVG is XML: names are case-sensitive
    EXPECT_EQ(matching("*|rect"), "r1 r2 r3 r4");
    EXPECT_EQ(matching("*"), "root g1 r1 c1 r2 t1 g2 g3 r3 p1 a1 r4 empty");
    EXPECT_EQ(matching(".b"), "r1 c1");
    EXPECT_EQ(matching(".a.b"), "r1");
    EXPECT_EQ(matching(".a"), "r1");
    EXPECT_EQ(matching(".A"), "r3");
    EXPECT_EQ(matching("#r2"), "r2");
    EXPECT_EQ(matching("rect#c1"), "");
    EXPECT_EQ(matching("*.top"), "g1");
    EXPECT_EQ(matching("rect, circle"), "r1 c1 r2 r3 r4");
}

TEST(CssSelectors, Attributes) {
    EXPECT_EQ(matching("[data-x]"), "r1 r2");
    EXPECT_EQ(matching("[ data-x = foo-bar ]"), "r1");
    EXPECT_EQ(matching("[data-x~=baz]"), "r2");
    EXPECT_EQ(matching("[data-x~='bar baz']"), "");
    EXPECT_EQ(matching("[data-x^=foo]"), "r1");
    EXPECT_EQ(matching("[data-x$=baz]"), "r2");
    EXPECT_EQ(matching("[data-x*='o-b']"), "r1");
    EXPECT_EQ(matching("[data-x^='']"), ""); // an empty value matches nothing
    EXPECT_EQ(matching("[lang|=en]"), "r1");
    EXPECT_EQ(matching("[lang|=en-US]"), "r1");
    EXPECT_EQ(matching("[lang|=e]"), "");
    EXPECT_EQ(matching("[data-x=FOO-BAR]"), "");
    EXPECT_EQ(matching("[data-x=FOO-BAR i]"), "r1");
    EXPECT_EQ(matching("[|data-x=foo-bar]"), "r1");
    EXPECT_EQ(matching("[xlink\\:href]"), "a1"); // pugixml keeps the prefix in the name
}

TEST(CssSelectors, Combinators) {
    EXPECT_EQ(matching("g rect"), "r1 r2 r3");
    EXPECT_EQ(matching("#g2 rect"), "r3");
    EXPECT_EQ(matching("g > rect"), "r1 r2 r3");
    EXPECT_EQ(matching("#g2 > rect"), "");
    EXPECT_EQ(matching("svg > a > rect"), "r4");
    EXPECT_EQ(matching("svg g g rect"), "r3");
    EXPECT_EQ(matching(".top rect"), "r1 r2");
    EXPECT_EQ(matching("rect + circle"), "c1");
    EXPECT_EQ(matching("circle + rect"), "r2");
    EXPECT_EQ(matching("rect ~ text"), "t1");
    EXPECT_EQ(matching("#c1 ~ *"), "r2 t1");
    EXPECT_EQ(matching("g + g"), "g2");
    EXPECT_EQ(matching("g ~ g"), "g2 empty");
    EXPECT_EQ(matching("g ~ a rect"), "r4");
    EXPECT_EQ(matching("#g1 + g > g > rect"), "r3");
    EXPECT_EQ(matching("svg>g>rect+circle~text"), "t1");
}

TEST(CssSelectors, PseudoClasses) {
    EXPECT_EQ(matching(":first-child"), "root g1 r1 g3 r3 r4");
    EXPECT_EQ(matching(":last-child"), "root t1 r3 p1 r4 empty");
    EXPECT_EQ(matching(":only-child"), "root r3 r4");
    EXPECT_EQ(matching(":root"), "root");
    EXPECT_EQ(matching(":empty"), "r1 c1 r2 r3 p1 r4 empty");
    EXPECT_EQ(matching("g > :nth-child(2n)"), "c1 t1 p1");
    EXPECT_EQ(matching("#g1 > :nth-child(odd)"), "r1 r2");
    EXPECT_EQ(matching("#g1 > :nth-child(-n + 2)"), "r1 c1");
    EXPECT_EQ(matching("#g1 > :nth-child(3)"), "r2");
    EXPECT_EQ(matching("#g1 > :nth-last-child(2)"), "r2");
    EXPECT_EQ(matching("rect:nth-of-type(2)"), "r2");
    EXPECT_EQ(matching("g:nth-last-of-type(1)"), "g3 empty");
    EXPECT_EQ(matching("rect:first-of-type"), "r1 r3 r4");
    EXPECT_EQ(matching("rect:last-of-type"), "r2 r3 r4");
    EXPECT_EQ(matching("#g1 > :only-of-type"), "c1 t1");
    EXPECT_EQ(matching("rect:not(.a)"), "r2 r3 r4");
    EXPECT_EQ(matching(":not(g, svg, rect)"), "c1 t1 p1 a1");
    EXPECT_EQ(matching("rect:not(g > *)"), "r4");
    EXPECT_EQ(matching(":is(circle, path)"), "c1 p1");
    EXPECT_EQ(matching(":where(#c1, 1x, #p1)"), "c1 p1"); // forgiving
    EXPECT_EQ(matching(":is()"), "");
    EXPECT_EQ(matching("a:link"), "a1");
    EXPECT_EQ(matching("rect:hover"), "");
    EXPECT_EQ(matching("rect:not(:hover)"), "r1 r2 r3 r4");
    EXPECT_EQ(matching("rect::before, circle"), "c1"); // valid, never matches
    EXPECT_EQ(matching("circle:AFTER, #r2"), "r2");
}

TEST(CssSelectors, InvalidAndUnsupportedDropTheRule) {
    struct Case {
        const char* selector;
        bool unsupported;
    };
    for (const Case& c :
         {Case{"rect::before .a", false}, Case{"[x]rect", false}, Case{"[data-x=]", false},
          Case{"[data-x==a]", false}, Case{"[data-x ~ = a]", false},
          Case{"rect:nth-child(2 n)", false}, Case{"rect:nth-child(+ 2)", false},
          Case{":not()", false}, Case{"rect.", false}, Case{"rect,", false}, Case{"> rect", false},
          Case{"[data-x=a x]", false}, Case{"rect.a*", false}, Case{"svg|rect", true},
          Case{":has(rect)", true}, Case{":nth-child(2 of .a)", true}, Case{":lang(en)", true},
          Case{"[*|href]", true}, Case{"[xlink|href]", true}}) {
        std::vector<CssProblem> problems;
        const StyleSheet sheet = sheet_of(std::string(c.selector) + " { fill: red }", &problems);
        ASSERT_EQ(problems.size(), 1u) << c.selector;
        EXPECT_EQ(problems[0].unsupported, c.unsupported)
            << c.selector << ": " << problems[0].message;
        EXPECT_NE(problems[0].message.find("rule ignored"), std::string::npos)
            << problems[0].message;
        EXPECT_TRUE(sheet.empty()) << c.selector;
    }
}

TEST(CssCascade, SpecificityThenSourceOrder) {
    const Doc doc(kTree);
    const StyleSheet sheet = sheet_of(R"(
        #r1 { fill: id }
        rect.a { fill: class-type }
        .a { fill: class }
        rect { fill: type }
        [data-x] { fill: attr }
        :first-child { fill: pseudo }
        * { fill: universal }
        :where(#r1) { fill: where }
        :is(#r1, rect) { fill: is }
        g rect { fill: type-type }
    )");
    EXPECT_EQ(cascade(sheet, doc, "r1"),
              "fill:universal fill:where fill:type fill:type-type fill:class fill:attr "
              "fill:pseudo fill:class-type fill:id fill:is");
}

TEST(CssCascade, SourceOrderAcrossSheetsAndImportantFlagged) {
    const Doc doc(kTree);
    StyleSheet sheet;
    std::vector<CssProblem> problems;
    sheet.parse("rect { fill: one; stroke: a !important }", problems);
    sheet.parse("rect { fill: two }\n#r2 { stroke: b }", problems);
    EXPECT_TRUE(problems.empty());
    EXPECT_EQ(sheet.size(), 3u);
    // The caller applies the important ones after the style attribute.
    EXPECT_EQ(cascade(sheet, doc, "r2"), "fill:one stroke:a! fill:two stroke:b");
}

TEST(CssCascade, SelectorListsCountOnceAtTheirBestSpecificity) {
    const Doc doc(kTree);
    const StyleSheet sheet = sheet_of("rect, #r1, .a { fill: list }\n.b { fill: b }");
    EXPECT_EQ(cascade(sheet, doc, "r1"), "fill:b fill:list");
    EXPECT_EQ(cascade(sheet, doc, "r2"), "fill:list");
}

// ---- The rule index against brute force on random documents ----

struct RandomCompound {
    std::string type, id, cls, attr; // attr: "[k]" or "[k=v]"
    int pseudo = 0; // 1 first-child, 2 last-child, 3 nth-child(2n+1), 4 nth-of-type(2), 5 :not(.c0)
};
struct RandomSelector {
    std::vector<RandomCompound> compounds;
    std::vector<char> combinators; // between compounds: ' ', '>', '+', '~'
    std::string text() const {
        static const char* pseudo[] = {
            "", ":first-child", ":last-child", ":nth-child(2n+1)", ":nth-of-type(2)", ":not(.c0)"};
        std::string s;
        for (std::size_t i = 0; i < compounds.size(); ++i) {
            const RandomCompound& c = compounds[i];
            if (i > 0)
                s += combinators[i - 1] == ' ' ? std::string(" ")
                                               : std::string(" ") + combinators[i - 1] + " ";
            std::string one = c.type + (c.id.empty() ? "" : "#" + c.id) +
                              (c.cls.empty() ? "" : "." + c.cls) + c.attr + pseudo[c.pseudo];
            s += one.empty() ? "*" : one;
        }
        return s;
    }
    int specificity() const {
        int s = 0;
        for (const RandomCompound& c : compounds)
            s += (c.id.empty() ? 0 : 10000) + (c.cls.empty() ? 0 : 100) +
                 (c.attr.empty() ? 0 : 100) + (c.pseudo ? 100 : 0) + (c.type.empty() ? 0 : 1);
        return s;
    }
};

pugi::xml_node element_sibling(pugi::xml_node n, bool previous) {
    do n = previous ? n.previous_sibling() : n.next_sibling();
    while (n && n.type() != pugi::node_element);
    return n;
}

// Straightforward definitions, with full backtracking.
bool brute_compound(const RandomCompound& c, pugi::xml_node e) {
    if (!c.type.empty() && c.type != e.name()) return false;
    if (!c.id.empty() && c.id != e.attribute("id").value()) return false;
    const auto has_class = [&](const std::string& k) {
        std::istringstream words(e.attribute("class").value());
        for (std::string w; words >> w;)
            if (w == k) return true;
        return false;
    };
    if (!c.cls.empty() && !has_class(c.cls)) return false;
    if (c.attr == "[k]" && !e.attribute("k")) return false;
    if (c.attr.size() > 3 && c.attr.substr(3, c.attr.size() - 4) != e.attribute("k").value())
        return false;
    int index = 1, of_type = 1;
    for (pugi::xml_node s = element_sibling(e, true); s; s = element_sibling(s, true)) {
        ++index;
        of_type += std::string(s.name()) == e.name();
    }
    switch (c.pseudo) {
    case 1:
        return index == 1;
    case 2:
        return !element_sibling(e, false);
    case 3:
        return index % 2 == 1;
    case 4:
        return of_type == 2;
    case 5:
        return !has_class("c0");
    }
    return true;
}

bool brute(const RandomSelector& s, std::size_t i, pugi::xml_node e) {
    if (!brute_compound(s.compounds[i], e)) return false;
    if (i == 0) return true;
    const auto parent = [](pugi::xml_node n) {
        n = n.parent();
        return n.type() == pugi::node_element ? n : pugi::xml_node();
    };
    switch (s.combinators[i - 1]) {
    case '>':
        return parent(e) && brute(s, i - 1, parent(e));
    case '+':
        return element_sibling(e, true) && brute(s, i - 1, element_sibling(e, true));
    case ' ':
        for (pugi::xml_node p = parent(e); p; p = parent(p))
            if (brute(s, i - 1, p)) return true;
        return false;
    default:
        for (pugi::xml_node p = element_sibling(e, true); p; p = element_sibling(p, true))
            if (brute(s, i - 1, p)) return true;
        return false;
    }
}

TEST(CssIndex, SameAsBruteForceOnRandomDocuments) {
    const char* names[] = {"g", "rect", "circle"};
    for (unsigned seed = 1; seed <= 12; ++seed) {
        std::mt19937 rng(seed);
        const auto pick = [&](int n) { return int(rng() % unsigned(n)); };
        // A random tree of 250 elements, up to 7 deep.
        std::string xml = "<svg>";
        int open = 0;
        for (int k = 0; k < 250; ++k) {
            while (open > 0 && (open >= 7 || pick(3) == 0)) xml += "</g>", --open;
            const char* name = names[pick(3)];
            xml += std::string("<") + name + " id=\"e" + std::to_string(k) + "\"";
            if (pick(2))
                xml += " class=\"c" + std::to_string(pick(4)) +
                       (pick(2) ? " c" + std::to_string(pick(4)) : "") + "\"";
            if (pick(3) == 0) xml += " k=\"v" + std::to_string(pick(3)) + "\"";
            if (std::string(name) == "g") {
                xml += ">";
                ++open;
            } else {
                xml += "/>";
            }
        }
        for (; open > 0; --open) xml += "</g>";
        xml += "</svg>";
        const Doc doc(xml.c_str());
        // 150 rules of one or two random selectors of up to 4 compounds.
        std::vector<std::vector<RandomSelector>> rules(150);
        std::string css;
        for (std::size_t r = 0; r < rules.size(); ++r) {
            for (int n = 1 + (pick(4) == 0); n > 0; --n) {
                RandomSelector s;
                for (int c = 1 + pick(4); c > 0; --c) {
                    RandomCompound rc;
                    if (pick(2)) rc.type = names[pick(3)];
                    if (pick(6) == 0) rc.id = "e" + std::to_string(pick(250));
                    if (pick(3) == 0) rc.cls = "c" + std::to_string(pick(4));
                    if (pick(5) == 0)
                        rc.attr = pick(2) ? "[k]" : "[k=v" + std::to_string(pick(3)) + "]";
                    if (pick(4) == 0) rc.pseudo = 1 + pick(5);
                    s.compounds.push_back(rc);
                    if (c > 1) s.combinators.push_back(" >+~"[pick(4)]);
                }
                css += (rules[r].empty() ? "" : ", ") + s.text();
                rules[r].push_back(s);
            }
            css += " { r: " + std::to_string(r) + " }\n";
        }
        const StyleSheet sheet = sheet_of(css);
        CssMatcher matcher(sheet, doc.tree);
        std::vector<const CssDeclaration*> got;
        for (const pugi::xml_node& e : doc.elements) {
            ASSERT_TRUE(matcher.match(PugiCssTree::node(e), got));
            std::vector<std::pair<int, std::size_t>> want; // (specificity, rule)
            for (std::size_t r = 0; r < rules.size(); ++r) {
                int best = -1;
                for (const RandomSelector& s : rules[r])
                    if (brute(s, s.compounds.size() - 1, e)) best = std::max(best, s.specificity());
                if (best >= 0) want.emplace_back(best, r);
            }
            std::sort(want.begin(), want.end());
            std::string w, g;
            for (const auto& [spec, r] : want) w += std::to_string(r) + " ";
            for (const CssDeclaration* d : got) g += d->value + " ";
            ASSERT_EQ(g, w) << "seed " << seed << ", element " << e.attribute("id").value()
                            << "\nsheet:\n"
                            << css;
        }
    }
}

// ---- Limits ----

TEST(CssLimits, LongAndDeepSelectorsAreDroppedNotRecursedInto) {
    std::string chain = "g";
    for (int i = 0; i < kCssMaxCompounds; ++i) chain += " > g";
    std::string nested = "rect";
    for (int i = 0; i <= kCssMaxNesting; ++i) nested = ":not(" + nested + ")";
    for (const std::string& s : {chain, nested}) {
        std::vector<CssProblem> problems;
        const StyleSheet sheet = sheet_of(s + " { fill: red } rect { fill: blue }", &problems);
        ASSERT_EQ(problems.size(), 1u) << s;
        EXPECT_TRUE(problems[0].unsupported) << problems[0].message;
        EXPECT_EQ(sheet.size(), 1u);
    }
    // Deep blocks cost no stack: 100000 open brackets, then the end.
    std::vector<CssProblem> problems;
    const StyleSheet deep =
        sheet_of(std::string(100000, '[') + std::string(100000, '('), &problems);
    EXPECT_TRUE(deep.empty());
    EXPECT_EQ(problems.size(), 1u);
}

TEST(CssLimits, SelectorCountIsCapped) {
    std::string css;
    for (std::size_t i = 0; i <= kCssMaxSelectors; ++i) css += ".c" + std::to_string(i) + "{a:b}";
    std::vector<CssProblem> problems;
    StyleSheet sheet = sheet_of(css, &problems);
    EXPECT_EQ(sheet.size(), kCssMaxSelectors);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].message.find("the limit"), std::string::npos);
    sheet.parse("rect { fill: red }", problems);
    EXPECT_EQ(problems.size(), 2u); // later sheets are ignored too
}

TEST(CssLimits, SiblingSelectorsStayLinearOnAFlatDocument) {
    // 20000 siblings: a walk over the earlier siblings for each would be
    // 2e8 steps; the per-parent caches make it a few per element.
    std::string xml = "<svg>";
    for (int i = 0; i < 20000; ++i) xml += i % 7 ? "<rect/>" : "<circle/>";
    xml += "<rect id=\"last\"/></svg>";
    const Doc doc(xml.c_str());
    const StyleSheet sheet =
        sheet_of("rect:nth-child(2n+1) { a: 1 } rect:nth-last-of-type(3) { b: 2 }"
                 "circle ~ rect { c: 3 } path ~ rect { d: 4 } rect:last-child { e: 5 }");
    CssMatcher m(sheet, doc.tree);
    std::vector<const CssDeclaration*> out;
    for (const pugi::xml_node& e : doc.elements) ASSERT_TRUE(m.match(PugiCssTree::node(e), out));
    EXPECT_LT(m.work(), 20u * 20000u) << m.work();
    // The last rect is child 20001: after a circle, odd, the last one.
    EXPECT_EQ(cascade(sheet, doc, "last"), "c:3 a:1 e:5");
}

TEST(CssLimits, TheWorkLimitStopsMatching) {
    const Doc doc(kTree);
    const StyleSheet sheet = sheet_of("* * * rect { a: 1 } * { b: 2 }");
    CssMatcher m(sheet, doc.tree, 5);
    std::vector<const CssDeclaration*> out;
    bool ok = true;
    for (const pugi::xml_node& e : doc.elements) ok = ok && m.match(PugiCssTree::node(e), out);
    EXPECT_FALSE(ok);
    EXPECT_FALSE(m.match(PugiCssTree::node(doc.elements[0]), out)); // and it stays stopped
}

TEST(CssLimits, GarbageNeverCrashes) {
    const char alphabet[] = "ab#.:>+~*[]()={}\"'\\;,/!@-_ 019\n\x80";
    std::mt19937 rng(7);
    const Doc doc(kTree);
    for (int round = 0; round < 2000; ++round) {
        std::string css;
        for (int n = int(rng() % 60); n > 0; --n) css += alphabet[rng() % (sizeof alphabet - 1)];
        std::vector<CssProblem> problems;
        StyleSheet sheet;
        sheet.parse(css, problems);
        CssMatcher m(sheet, doc.tree);
        std::vector<const CssDeclaration*> out;
        for (const pugi::xml_node& e : doc.elements)
            ASSERT_TRUE(m.match(PugiCssTree::node(e), out)) << css;
        for (const CssProblem& p : problems) ASSERT_GE(p.line, 1) << css;
    }
}

} // namespace
} // namespace casteljau
