// Namespace prefixes of their own (svg/detail/xml_namespaces.h): SVG read by
// namespace, as browsers and librsvg read it, not by the prefix written.
#include "casteljau/svg/reader.h"

#include <gtest/gtest.h>
#include <string>
#include <variant>

namespace casteljau {
namespace {

int shape_count(const Group& g) {
    int n = 0;
    for (const Node& c : g.children)
        n += std::holds_alternative<Shape>(c.item) ? 1 : shape_count(std::get<Group>(c.item));
    return n;
}

// What XSLT and XHTML write (svg:), and Python's ElementTree unless told
// otherwise (ns0:, xlink as ns1:); before, refused: "the root element is
// <svg:svg>, not <svg>".
TEST(XmlNamespaces, PrefixedSvgIsReadAsSvg) {
    const SvgResult svg = parse_svg(
        R"(<svg:svg xmlns:svg="http://www.w3.org/2000/svg" width="10" height="10">
             <svg:rect width="5" height="5"/><svg:g><svg:circle r="2"/></svg:g></svg:svg>)",
        "a.svg");
    ASSERT_TRUE(svg.scene) << svg.error;
    EXPECT_EQ(svg.scene->width, 10);
    EXPECT_EQ(shape_count(svg.scene->root), 2);
    const SvgResult etree = parse_svg(
        R"(<ns0:svg xmlns:ns0="http://www.w3.org/2000/svg" xmlns:ns1="http://www.w3.org/1999/xlink"
             width="10" height="10"><ns0:defs><ns0:rect id="r" width="5" height="5"/></ns0:defs>
             <ns0:use ns1:href="#r" x="2"/><ns0:use ns1:href="#r" x="4"/></ns0:svg>)",
        "b.svg");
    ASSERT_TRUE(etree.scene) << etree.error;
    EXPECT_TRUE(etree.warnings.empty()) << etree.warnings[0].text();
    EXPECT_EQ(shape_count(etree.scene->root), 2) << "both uses find the rect";
}

// Scopes: a prefix means what its nearest declaration says; elements of
// other namespaces stay foreign (not drawn), whatever their prefix.
TEST(XmlNamespaces, PrefixesAreScopedAndOtherNamespacesStayForeign) {
    const SvgResult r = parse_svg(
        R"(<svg xmlns="http://www.w3.org/2000/svg" xmlns:s="http://www.w3.org/2000/svg"
             xmlns:i="http://ns.adobe.com/AdobeIllustrator/10.0/" width="10" height="10">
             <s:rect width="1" height="1"/><i:rect width="1" height="1"/>
             <g xmlns:s="urn:other"><s:rect width="1" height="1"/></g>
             <g xmlns:i="http://www.w3.org/2000/svg"><i:rect width="1" height="1"/></g></svg>)",
        "c.svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_EQ(shape_count(r.scene->root), 2) << "s:rect at the top, i:rect in the last group";
}

// A default namespace other than SVG's makes the unprefixed elements under
// it foreign, an SVG prefix still SVG (the SVG 1.1 test suite's
// struct-frag-05-t); before, the notsvg circle was drawn. An inner
// declaration of SVG's default brings them back.
TEST(XmlNamespaces, UnprefixedElementsUnderAnotherDefaultNamespaceAreForeign) {
    const SvgResult r = parse_svg(
        R"(<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">
             <s:g xmlns="http://www.example.org/notsvg" xmlns:s="http://www.w3.org/2000/svg">
               <s:circle r="2" fill="green"/><circle r="2" fill="red"/>
               <g xmlns="http://www.w3.org/2000/svg"><rect width="1" height="1"/></g></s:g>
             <g xmlns=""><rect width="1" height="1" fill="red"/></g></svg>)",
        "e.svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_EQ(shape_count(r.scene->root), 2) << "s:circle and the inner rect";
    const SvgResult foreign_root =
        parse_svg(R"(<svg xmlns="urn:other" width="10" height="10"><rect/></svg>)", "f.svg");
    EXPECT_FALSE(foreign_root.scene) << "no SVG root";
    EXPECT_NE(foreign_root.error.find("f.svg:1: the root element is <svg>, not <svg> of the SVG"),
              std::string::npos)
        << foreign_root.error;
    const SvgResult xhtml =
        parse_svg("\n<html xmlns=\"http://www.w3.org/1999/xhtml\"><svg/></html>", "x.html");
    EXPECT_NE(xhtml.error.find("x.html:2: the root element is <html>, not <svg>"),
              std::string::npos)
        << xhtml.error;
}

// A renamed element keeps its line and its name as written in warnings
// (pugixml forgets a renamed node's offset: they were all at line 0), and
// a prefixed root its prolog's xml-stylesheet links.
TEST(XmlNamespaces, RenamedElementsKeepTheirLinesAndWrittenNames) {
    const SvgResult r = parse_svg(
        R"(<?xml-stylesheet href="data:text/css,rect{fill:blue}"?>
<svg:svg xmlns:svg="http://www.w3.org/2000/svg" width="10" height="10">
  <svg:rect width="5" height="5" rx="-1"/></svg:svg>)",
        "g.svg");
    ASSERT_TRUE(r.scene) << r.error;
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].line, 3);
    EXPECT_EQ(r.warnings[0].element, "svg:rect");
    const Shape& s = std::get<Shape>(r.scene->root.children.at(0).item);
    EXPECT_EQ(s.source_line, 3);
    ASSERT_TRUE(s.fill);
    EXPECT_EQ(s.fill->color, (Rgba{0, 0, 1, 1})) << "the linked sheet applies";
}

// An attribute in the SVG namespace (svg:fill) is not the attribute fill:
// SVG's are in no namespace, and browsers ignore it. Inkscape declares
// xmlns:svg in every file; a comment's "xmlns:" does not stop the scan.
TEST(XmlNamespaces, OnlyXlinkAttributesAreRenamed) {
    const SvgResult r = parse_svg(
        R"(<!-- xmlns:svg = odd; don't --><svg:svg xmlns:svg="http://www.w3.org/2000/svg"
             width="10" height="10"><svg:rect width="5" height="5" fill="blue" svg:fill="red"/>
             </svg:svg>)",
        "d.svg");
    ASSERT_TRUE(r.scene) << r.error;
    const Shape& s = std::get<Shape>(r.scene->root.children.at(0).item);
    ASSERT_TRUE(s.fill);
    EXPECT_EQ(s.fill->color, (Rgba{0, 0, 1, 1}));
}

} // namespace
} // namespace casteljau
