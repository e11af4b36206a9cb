// <use> of elements in other files (svg/external_use.cpp): sprite sheets
// drawn as SVG 2 says, styled and resolved in their own file, and every way
// such a reference can fail: one warning on the use, nothing drawn.
#include "image_files.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

using namespace testing;

// Its style sheet makes .mark red; its #g is blue (the using documents below
// have a red #g of their own); #broken's fill is invalid, on line 7.
constexpr const char* kSprites =
    R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">
<style>.mark { fill: #ff0000 }</style>
<linearGradient id="g"><stop offset="0" stop-color="#0000ff"/></linearGradient>
<symbol id="sym" viewBox="0 0 1 1"><rect class="mark" width="1" height="1"/></symbol>
<rect id="plain" width="4" height="4"/>
<rect id="graded" width="4" height="4" fill="url(#g)"/>
<rect id="broken" width="4" height="4" fill="nonsense"/>
</svg>)svg";

constexpr Premul kBlack{0, 0, 0, 1}, kLime{0, 1, 0, 1};

struct Sprites {
    TempDir dir;
    Sprites() {
        write_text(dir / "s.svg", kSprites);
        write_text(dir / "whole.svg", cat(kSvgOpen, R"(4" height="4" viewBox="0 0 1 1">)"
                                                    R"(<rect width="1" height="1" fill="blue"/>)"
                                                    "</svg>"));
    }
    // `body` as the 10 x 10 document `name` in the folder.
    void file(const std::string& name, const std::string& body) const {
        write_text(dir / name, document(body, 10, 10));
    }
    Drawn render(const std::string& body, SvgOptions o = {}) const {
        return testing::render(body, 10, 10, dir.str(), o);
    }
};

Premul at(const Drawn& d, int x, int y) { return d.canvas.row(y)[x]; }

TEST(ExternalUse, ASymbolTakesTheUsesSizeAndItsOwnFilesStyleSheet) {
    const Sprites s;
    // The sprite's style sheet sets the fill; the use's green is only inherited.
    const Drawn d =
        s.render(R"(<use href="s.svg#sym" x="2" y="2" width="6" height="6" fill="lime"/>)");
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(at(d, 5, 5), kRed, 1e-6f));
    EXPECT_TRUE(near(at(d, 2, 7), kRed, 1e-6f));
    EXPECT_TRUE(near(at(d, 1, 1), kNone, 1e-6f));
    EXPECT_TRUE(near(at(d, 8, 8), kNone, 1e-6f));
}

TEST(ExternalUse, WhatTheSpriteLeavesUnsetIsInheritedFromTheUse) {
    const Sprites s;
    const Drawn d = s.render(R"(<use href="s.svg#plain" x="1" y="1" fill="lime"/>)");
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(at(d, 2, 2), kLime, 1e-6f));
    EXPECT_TRUE(near(at(d, 0, 0), kNone, 1e-6f));
    EXPECT_TRUE(near(at(d, 5, 5), kNone, 1e-6f));
}

// SVG 2, 16.2 (processing URLs): url(#g) in the sprite file is that file's #g.
// librsvg 2.54 looks it up in the using file (here red; with none, the fill
// is none).
TEST(ExternalUse, ItsReferencesResolveInItsOwnFile) {
    const Sprites s;
    const Drawn d =
        s.render(R"(<linearGradient id="g"><stop offset="0" stop-color="red"/></linearGradient>)"
                 R"(<use href="s.svg#graded"/>)");
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(at(d, 2, 2), kBlue, 1e-6f));
}

// SVG 2, 5.6: an href without a fragment names the file's root element (its
// own viewport, sized by the use). librsvg 2.54 draws nothing (its issue 836).
TEST(ExternalUse, AnHrefWithoutAFragmentDrawsTheWholeFile) {
    const Sprites s;
    const Drawn d = s.render(R"(<use href="whole.svg" x="1" y="1" width="8" height="8"/>)");
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(at(d, 1, 1), kBlue, 1e-6f));
    EXPECT_TRUE(near(at(d, 8, 8), kBlue, 1e-6f));
    EXPECT_TRUE(near(at(d, 9, 9), kNone, 1e-6f));
    EXPECT_TRUE(near(at(d, 0, 0), kNone, 1e-6f));
}

TEST(ExternalUse, AProblemInsideTheFileNamesItsFileAndLine) {
    const Sprites s;
    const Drawn d = s.render(R"(<use href="s.svg#broken"/>)");
    ASSERT_EQ(d.warnings.size(), 1u) << warnings_text(d.warnings);
    EXPECT_TRUE(d.warnings[0].file.ends_with("s.svg")) << d.warnings[0].file;
    EXPECT_NE(d.warnings[0].file, "t.svg");
    EXPECT_EQ(d.warnings[0].line, 7);
    EXPECT_EQ(d.warnings[0].element, "rect");
    // The invalid fill is ignored: the initial black.
    EXPECT_TRUE(near(at(d, 2, 2), kBlack, 1e-6f));
}

TEST(ExternalUse, AFileThatNamesItselfIsTheSameDocument) {
    const Sprites s;
    s.file("self.svg", R"(<rect id="r" width="2" height="2" fill="lime"/>)"
                       "\n"
                       R"(<use href="self.svg#r" x="5" y="5"/>)");
    SvgOptions no_files; // it reads no file to do so
    no_files.max_images = 0;
    const SvgResult doc = read_svg_file(s.dir / "self.svg", no_files);
    const Drawn d = draw(doc, 10, 10);
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(at(d, 6, 6), kLime, 1e-6f));
    // Its own element instanced inside itself is the use-in-its-target case.
    s.file("loop.svg", R"(<g id="x"><use href="loop.svg#x"/></g>)");
    const SvgResult loop = read_svg_file(s.dir / "loop.svg");
    ASSERT_EQ(loop.warnings.size(), 1u) << warnings_text(loop.warnings);
    EXPECT_NE(loop.warnings[0].message.find("contains the use itself"), std::string::npos);
}

TEST(ExternalUse, EveryFailedReferenceIsOneWarningOnTheUseAndDrawsNothing) {
    const Sprites s;
    write_text(s.dir / "bad.svg", "<svg xmlns=\"http://www.w3.org/2000/svg\"><rect");
    write_text(s.dir / "page.svg", "<html><p id=\"x\"/></html>");
    const TempDir outside;
    write_text(outside / "o.svg", kSprites);
    const std::string outside_href = fs::relative(outside.path / "o.svg", s.dir.path).string();
    const std::pair<std::string, std::string> cases[] = {
        {"http://example.com/s.svg#sym", "network access is not allowed"},
        {"//example.com/s.svg#sym", "network access is not allowed"},
        {outside_href + "#plain", "outside the SVG's folder"},
        {"data:image/svg+xml,%3Csvg/%3E#x", "reads no data: URL"},
        {"missing.svg#plain", "cannot be drawn from"},
        {"s.svg#nothere", "names no element"},
        {"bad.svg#x", "malformed XML"},
        {"page.svg#x", "not <svg>"},
    };
    for (const auto& [href, why] : cases) {
        const Drawn d = s.render(cat(cat(R"(<use href=")", href), R"(" fill="lime"/>)"));
        ASSERT_EQ(d.warnings.size(), 1u) << href << ": " << warnings_text(d.warnings);
        EXPECT_EQ(d.warnings[0].element, "use") << href;
        EXPECT_EQ(d.warnings[0].line, 1) << href;
        EXPECT_NE(d.warnings[0].message.find(why), std::string::npos)
            << href << ": " << d.warnings[0].message;
        EXPECT_TRUE(blank(d.canvas)) << href;
    }
    SvgOptions strict;
    strict.strict = true;
    strict.base_dir = s.dir.str();
    const SvgResult r =
        parse_svg(document(R"(<use href="missing.svg#plain"/>)", 10, 10), "t.svg", strict);
    EXPECT_FALSE(r.scene);
    EXPECT_NE(r.error.find("cannot be drawn from"), std::string::npos) << r.error;
}

TEST(ExternalUse, ACycleThroughFilesIsFoundWhereItCloses) {
    const Sprites s;
    s.file("a.svg", R"(<g id="x"><use href="b.svg#y"/></g>)");
    s.file("b.svg", "<g id=\"y\"><rect width=\"3\" height=\"3\"/>\n"
                    R"(<use href="a.svg#x" x="5"/></g>)");
    const Drawn d = s.render(R"(<use href="a.svg#x" fill="lime"/>)");
    ASSERT_EQ(d.warnings.size(), 1u) << warnings_text(d.warnings);
    EXPECT_TRUE(d.warnings[0].file.ends_with("b.svg")) << d.warnings[0].file;
    EXPECT_EQ(d.warnings[0].line, 2);
    EXPECT_NE(d.warnings[0].message.find("makes a cycle"), std::string::npos);
    EXPECT_TRUE(near(at(d, 1, 1), kLime, 1e-6f)) << "the rectangle before the cycle is drawn";
    EXPECT_TRUE(near(at(d, 6, 1), kNone, 1e-6f));
}

TEST(ExternalUse, FilesDrawnFromFilesStopAtMaxImageNesting) {
    const Sprites s;
    // f0.svg#x draws f1.svg#x, ... f9.svg#x a rectangle.
    for (int i = 0; i < 10; ++i) {
        std::string body = R"(<g id="x">)";
        body += i < 9 ? cat(cat(R"(<use href="f)", std::to_string(i + 1)), R"(.svg#x"/>)")
                      : std::string(R"(<rect width="3" height="3"/>)");
        write_text(s.dir / cat(cat("f", std::to_string(i)), ".svg"),
                   document(body + "</g>", 10, 10));
    }
    SvgOptions o;
    o.max_image_nesting = 3;
    const Drawn d = s.render(R"(<use href="f0.svg#x"/>)", o);
    ASSERT_EQ(d.warnings.size(), 1u) << warnings_text(d.warnings);
    EXPECT_NE(d.warnings[0].message.find("nested deeper than 3"), std::string::npos)
        << d.warnings[0].message;
    EXPECT_TRUE(blank(d.canvas));
    o.max_image_nesting = 10;
    const Drawn all = s.render(R"(<use href="f0.svg#x" fill="lime"/>)", o);
    EXPECT_TRUE(all.warnings.empty()) << warnings_text(all.warnings);
    EXPECT_TRUE(near(at(all, 1, 1), kLime, 1e-6f));
}

TEST(ExternalUse, InstancesCountAgainstMaxElementsAndFilesAgainstMaxImages) {
    const Sprites s;
    std::string group = R"(<g id="many">)";
    for (int i = 0; i < 30; ++i) group += R"(<rect width="1" height="1"/>)";
    s.file("many.svg", group + "</g>");
    SvgOptions o;
    o.base_dir = s.dir.str();
    o.max_elements = 100;
    std::string uses;
    for (int i = 0; i < 3; ++i) uses += R"(<use href="many.svg#many"/>)";
    EXPECT_TRUE(parse_svg(document(uses, 10, 10), "t.svg", o).scene) << "3 x 31 elements and 4";
    uses += R"(<use href="many.svg#many"/>)";
    const SvgResult over = parse_svg(document(uses, 10, 10), "t.svg", o);
    EXPECT_FALSE(over.scene);
    EXPECT_NE(over.error.find("more than 100 elements"), std::string::npos) << over.error;
    // Each file is read once however often it is used; a second file is
    // one more against max_images.
    SvgOptions one;
    one.max_images = 1;
    const Drawn d = s.render(R"(<use href="s.svg#plain" fill="lime"/>)"
                             R"(<use href="s.svg#plain" x="5" y="5" fill="lime"/>)"
                             R"(<use href="whole.svg" x="5"/>)",
                             one);
    ASSERT_EQ(d.warnings.size(), 1u) << warnings_text(d.warnings);
    EXPECT_NE(d.warnings[0].message.find("more than 1 images and files"), std::string::npos)
        << d.warnings[0].message;
    EXPECT_TRUE(near(at(d, 1, 1), kLime, 1e-6f));
    EXPECT_TRUE(near(at(d, 6, 6), kLime, 1e-6f));
    EXPECT_TRUE(near(at(d, 6, 1), kNone, 1e-6f));
}

// Each file is read once for the whole document, whichever file uses it: a
// lattice of files each using the next two would otherwise be read 2^depth
// times (review: 16 files, 45 s and 9.8 GB before).
TEST(ExternalUse, AFileUsedFromSeveralFilesIsReadOnce) {
    const Sprites s;
    s.file("c.svg", R"(<rect id="r" width="2" height="2"/>)");
    s.file("a.svg", R"(<g id="x"><use href="c.svg#r"/></g>)");
    s.file("b.svg", R"(<g id="x"><use href="c.svg#r" x="5"/></g>)");
    SvgOptions three;
    three.max_images = 3; // a, b and c, each once
    const Drawn d =
        s.render(R"(<use href="a.svg#x" fill="lime"/><use href="b.svg#x" fill="lime"/>)", three);
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(at(d, 1, 1), kLime, 1e-6f));
    EXPECT_TRUE(near(at(d, 6, 1), kLime, 1e-6f));
}

// a.svg#x draws b.svg#y, which draws a.svg#z: no cycle, and the reader of
// a.svg, in the middle of drawing #x, draws #z and goes on where it was.
TEST(ExternalUse, AReaderDrawingAlreadyDrawsAgainAndGoesOn) {
    const Sprites s;
    s.file("a.svg", R"(<g id="x"><use href="b.svg#y"/><rect y="5" width="2" height="2"/></g>)"
                    R"(<rect id="z" width="2" height="2"/>)");
    s.file("b.svg", R"(<g id="y"><use href="a.svg#z" x="5"/></g>)");
    const Drawn d = s.render(R"(<use href="a.svg#x" fill="lime"/>)");
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(at(d, 6, 1), kLime, 1e-6f)) << "a.svg#z through b.svg";
    EXPECT_TRUE(near(at(d, 1, 6), kLime, 1e-6f)) << "the rest of a.svg#x";
}

// The use is the context element of what it draws (SVG 2, 13.3), its
// objectBoundingBox paint measured on that: review, a bbox gradient through
// context-fill drew nothing from another file (measuring re-entered the use
// and took it for a cycle).
TEST(ExternalUse, ContextPaintsTakeTheUsesBox) {
    const Sprites s;
    s.file("c.svg", R"(<rect id="r" width="10" height="10" style="fill: context-fill"/>)");
    const Drawn d = s.render(R"(<linearGradient id="g"><stop offset="0.5" stop-color="lime"/>)"
                             R"(<stop offset="0.5" stop-color="blue"/></linearGradient>)"
                             R"x(<use href="c.svg#r" fill="url(#g)"/>)x");
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(at(d, 2, 5), kLime, 1e-6f));
    EXPECT_TRUE(near(at(d, 8, 5), kBlue, 1e-6f));
}

// Custom properties set on the use reach the sprite's var() (the document's
// own text has none), and a sprite file's problems in reading are told
// even when its use then fails.
TEST(ExternalUse, CustomPropertiesReachTheSpriteAndItsProblemsAreTold) {
    const Sprites s;
    write_text(s.dir / "v.svg",
               cat(kSvgOpen, "10\" height=\"10\">\n<style>.a:: {}</style>"
                             R"x(<rect id="r" width="4" height="4" style="fill: var(--c, red)"/>)x"
                             "</svg>"));
    const Drawn d = s.render(R"(<use href="v.svg#r" style="--c: lime"/><use href="v.svg#no"/>)");
    ASSERT_EQ(d.warnings.size(), 2u) << warnings_text(d.warnings);
    EXPECT_TRUE(d.warnings[0].file.ends_with("v.svg")) << warnings_text(d.warnings);
    EXPECT_EQ(d.warnings[0].line, 2);
    EXPECT_NE(d.warnings[1].message.find("names no element"), std::string::npos);
    EXPECT_TRUE(near(at(d, 2, 2), kLime, 1e-6f));
}

// A sprite in a folder of its own may use files elsewhere in the SVG's folder.
TEST(ExternalUse, FilesStayWithinTheSvgsFolderNotTheirOwn) {
    const Sprites s;
    fs::create_directories(s.dir.path / "icons");
    fs::create_directories(s.dir.path / "shared");
    s.file("shared/r.svg", R"(<rect id="r" width="4" height="4"/>)");
    s.file("icons/i.svg", R"(<use id="i" href="../shared/r.svg#r"/>)");
    const Drawn d = s.render(R"(<use href=" icons/i.svg#i " fill="lime"/>)");
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(at(d, 2, 2), kLime, 1e-6f));
}

// main draws b.svg#x, which draws c.svg#y, which draws b.svg#z: b.svg's
// warnings come in the order its elements are drawn (second review: the
// inner instance took the outer one's warnings along, after its own).
TEST(ExternalUse, WarningsComeInDrawingOrderThroughAReenteredFile) {
    const Sprites s;
    s.file("b.svg", "<g id=\"x\">\n<rect width=\"-1\" height=\"2\"/>\n"
                    "<use href=\"c.svg#y\"/>\n"
                    "<rect width=\"-2\" height=\"2\"/></g>\n"
                    "<rect id=\"z\" width=\"-3\" height=\"2\"/>");
    s.file("c.svg", R"(<g id="y"><rect width="-4" height="2"/><use href="b.svg#z"/></g>)");
    const Drawn d = s.render(R"(<use href="b.svg#x"/>)");
    ASSERT_EQ(d.warnings.size(), 4u) << warnings_text(d.warnings);
    const std::pair<const char*, int> order[] = {
        {"b.svg", 2}, {"c.svg", 1}, {"b.svg", 5}, {"b.svg", 4}};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_TRUE(d.warnings[i].file.ends_with(order[i].first)) << warnings_text(d.warnings);
        EXPECT_EQ(d.warnings[i].line, order[i].second) << warnings_text(d.warnings);
    }
}

// The bytes of all files drawn from are bounded before they are held: a
// file is read (and inflated) up to what is left of max_file_bytes.
TEST(ExternalUse, TheFilesBytesAreBoundedInAll) {
    const Sprites s;
    const std::string pad(600, ' ');
    s.file("p.svg", R"(<rect id="r" width="2" height="2"/>)" + pad);
    s.file("q.svg", R"(<rect id="r" width="2" height="2"/>)" + pad);
    SvgOptions o;
    o.max_file_bytes = 1000;
    const Drawn d =
        s.render(R"(<use href="p.svg#r" fill="lime"/><use href="q.svg#r" x="5" fill="lime"/>)", o);
    ASSERT_EQ(d.warnings.size(), 1u) << warnings_text(d.warnings);
    EXPECT_NE(d.warnings[0].message.find("exceed the limit"), std::string::npos)
        << d.warnings[0].message;
    EXPECT_TRUE(near(at(d, 1, 1), kLime, 1e-6f));
    EXPECT_TRUE(near(at(d, 6, 1), kNone, 1e-6f));
}

// An href with spaces around it counts in the bound on what uses expand to,
// checked before anything is built (second review: 10^9 instances were
// built up to the element limit).
TEST(ExternalUse, SpacesAroundAnHrefCountInTheExpansionBound) {
    std::string body = R"(<rect id="a0" width="1" height="1"/>)";
    for (int i = 1; i <= 9; ++i) {
        body += cat(cat(R"(<g id="a)", std::to_string(i)), "\">");
        for (int k = 0; k < 10; ++k)
            body += cat(cat(R"(<use href=" #a)", std::to_string(i - 1)), " \"/>");
        body += "</g>";
    }
    const SvgResult r = parse_svg(document(body, 10, 10), "t.svg");
    EXPECT_FALSE(r.scene);
    EXPECT_NE(r.error.find("once <use> is expanded"), std::string::npos) << r.error;
}

// A file drawn from may draw images from elsewhere in the SVG's folder, as
// it may use files and sheets; an image's problem found while a use is
// measured is told by the walk that draws (second review: never told).
TEST(ExternalUse, ItsImagesStayWithinTheSvgsFolderAndTheirProblemsAreTold) {
    const Sprites s;
    fs::create_directories(s.dir.path / "icons");
    write_green(s.dir / "pic.png", 2, 2);
    s.file("icons/i.svg", R"(<image id="i" href="../pic.png" width="4" height="4"/>)");
    const Drawn d = s.render(R"(<use href="icons/i.svg#i"/>)");
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(at(d, 2, 2), kLime, 1e-6f));
    const Drawn missing =
        s.render(R"(<linearGradient id="g"><stop offset="0" stop-color="red"/></linearGradient>)"
                 R"(<g id="m"><image href="missing.png" width="4" height="4"/></g>)"
                 R"x(<use href="#m" fill="url(#g)"/>)x");
    ASSERT_EQ(missing.warnings.size(), 1u) << warnings_text(missing.warnings);
    EXPECT_NE(missing.warnings[0].message.find("cannot be drawn"), std::string::npos);
}

} // namespace
} // namespace casteljau
