// Style sheets in files (svg/linked_style_sheets.cpp): xml-stylesheet links
// and @import rules, their order in the cascade, where their files may come
// from, and every way one fails: a warning at the rule or link, naming the
// file and line, and the rest of the styling as it would be without it.
#include "image_files.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

using namespace testing;

constexpr Premul kLime{0, 1, 0, 1}, kBlack{0, 0, 0, 1};

struct Sheets {
    TempDir dir;
    // `prolog` before the root, `body` in a 40 x 10 document.
    Drawn render(const std::string& prolog, const std::string& body, SvgOptions o = {}) const {
        o.base_dir = dir.str();
        const SvgResult doc = parse_svg(prolog + document(body, 40, 10), "t.svg", o);
        EXPECT_TRUE(doc.scene) << doc.error;
        return draw(doc, 40, 10);
    }
    void write(const std::string& name, const std::string& css) const {
        fs::create_directories((dir.path / name).parent_path());
        write_text(dir / name, css);
    }
};

// The fill of the 10 px square at column 10 i.
Premul square(const Drawn& d, int i) { return d.canvas.row(5)[10 * i + 5]; }

constexpr const char* kFour = R"(<rect id="p" width="10" height="10"/>)"
                              R"(<rect class="x" x="10" width="10" height="10"/>)"
                              R"(<rect class="y" x="20" width="10" height="10"/>)"
                              R"(<rect class="z" x="30" width="10" height="10"/>)";

TEST(LinkedStyleSheets, LinkedSheetsThenEachSheetsImportsThenItsOwnRules) {
    const Sheets s;
    s.write("base.css", "rect { fill: blue } .x { fill: red } .z { fill: red }");
    // Its import's path is relative to it.
    s.write("more/over.css", "@import 'inner.css';\n.x { fill: yellow } .z { fill: blue }");
    s.write("more/inner.css", ".y { fill: #00ff00 }");
    const Drawn d = s.render(R"(<?xml version="1.0"?>)"
                             "\n"
                             R"(<?xml-stylesheet type="text/css" href="base.css"?>)"
                             "\n",
                             R"(<style>@import "more/over.css"; .x { fill: #00ff00 }</style>)" +
                                 std::string(kFour));
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(square(d, 0), kBlue, 1e-6f)) << "the linked sheet alone";
    EXPECT_TRUE(near(square(d, 1), kLime, 1e-6f)) << "the <style>'s own rule, last";
    EXPECT_TRUE(near(square(d, 2), kLime, 1e-6f)) << "an import's import";
    EXPECT_TRUE(near(square(d, 3), kBlue, 1e-6f)) << "the import after the linked sheet";
}

TEST(LinkedStyleSheets, AlternateOtherTypesAndUnmatchedMediaAreNotApplied) {
    const Sheets s;
    s.write("red.css", "rect { fill: red }");
    s.write("lime.css", "#p { fill: #00ff00 }");
    const Drawn d =
        s.render(R"(<?xml-stylesheet href="red.css" alternate="yes"?>)"
                 R"(<?xml-stylesheet href="red.css" type="text/xsl"?>)"
                 R"(<?xml-stylesheet href="red.css" media="print"?>)"
                 R"x(<?xml-stylesheet href='lime.css' media="screen and (min-width: 20px)"?>)x",
                 std::string(R"x(<style>@import "red.css" (max-width: 5px);</style>)x") + kFour);
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(square(d, 0), kLime, 1e-6f));
    EXPECT_TRUE(near(square(d, 1), kBlack, 1e-6f));
}

TEST(LinkedStyleSheets, ADataUrlSheetIsReadInPlace) {
    const Sheets s;
    const Drawn d =
        s.render("", std::string(R"(<style>@import url("data:text/css,%23p%7Bfill:%2300ff00%7D");)"
                                 "</style>") +
                         kFour);
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(square(d, 0), kLime, 1e-6f));
}

TEST(LinkedStyleSheets, AProblemInsideASheetFileNamesItsFileAndLine) {
    const Sheets s;
    s.write("bad.css", "#p { fill: #00ff00 }\n\n.x:: { fill: red }\n");
    const Drawn d = s.render(R"(<?xml-stylesheet href="bad.css"?>)", kFour);
    ASSERT_EQ(d.warnings.size(), 1u) << warnings_text(d.warnings);
    EXPECT_TRUE(d.warnings[0].file.ends_with("bad.css")) << d.warnings[0].file;
    EXPECT_EQ(d.warnings[0].line, 3);
    EXPECT_EQ(d.warnings[0].element, "xml-stylesheet");
    EXPECT_TRUE(near(square(d, 0), kLime, 1e-6f)) << "the rest of the sheet applies";
}

TEST(LinkedStyleSheets, EachFailedSheetIsOneWarningAtItsRule) {
    const Sheets s;
    s.write("a.css", "@import 'b.css';\n#p { fill: #00ff00 }");
    s.write("b.css", "\n@import 'a.css';");
    const TempDir outside;
    write_text(outside / "o.css", "rect { fill: red }");
    const std::string outside_href = fs::relative(outside.path / "o.css", s.dir.path).string();
    const std::pair<std::string, std::string> cases[] = {
        {"http://example.com/s.css", "network access is not allowed"},
        {outside_href, "outside the SVG's folder"},
        {"missing.css", "cannot read"},
        {"data:text/css;base64,@@@", "invalid base64"},
    };
    for (const auto& [href, why] : cases) {
        const Drawn d = s.render("", "\n<style>\n@import '" + href + "';</style>" + kFour);
        ASSERT_EQ(d.warnings.size(), 1u) << href << ": " << warnings_text(d.warnings);
        EXPECT_EQ(d.warnings[0].file, "t.svg") << href;
        EXPECT_EQ(d.warnings[0].line, 3) << href;
        EXPECT_EQ(d.warnings[0].element, "style") << href;
        EXPECT_NE(d.warnings[0].message.find(why), std::string::npos)
            << href << ": " << d.warnings[0].message;
        EXPECT_TRUE(near(square(d, 0), kBlack, 1e-6f)) << href;
    }
    // a.css imports b.css, which imports a.css: told where the cycle closes,
    // and a.css's rules apply once.
    const Drawn cycle = s.render(R"(<?xml-stylesheet href="a.css"?>)", kFour);
    ASSERT_EQ(cycle.warnings.size(), 1u) << warnings_text(cycle.warnings);
    EXPECT_TRUE(cycle.warnings[0].file.ends_with("b.css")) << cycle.warnings[0].file;
    EXPECT_EQ(cycle.warnings[0].line, 2);
    EXPECT_NE(cycle.warnings[0].message.find("imports itself"), std::string::npos);
    EXPECT_TRUE(near(square(cycle, 0), kLime, 1e-6f));
    // Strictly read, a sheet that cannot be read is the error.
    SvgOptions strict;
    strict.strict = true;
    strict.base_dir = s.dir.str();
    const SvgResult r =
        parse_svg(document("<style>@import 'missing.css';</style>", 10, 10), "t.svg", strict);
    EXPECT_FALSE(r.scene);
    EXPECT_NE(r.error.find("cannot read"), std::string::npos) << r.error;
}

TEST(LinkedStyleSheets, ImportsStopAtTheirNestingAndFileLimits) {
    const Sheets s;
    // i.css imports (i + 1).css, down to 30.css, which paints #p.
    for (int i = 0; i < 30; ++i)
        s.write(cat(std::to_string(i), ".css"),
                cat(cat("@import '", std::to_string(i + 1)), ".css';"));
    s.write("30.css", "#p { fill: #00ff00 }");
    const Drawn deep = s.render("", std::string("<style>@import '0.css';</style>") + kFour);
    ASSERT_EQ(deep.warnings.size(), 1u) << warnings_text(deep.warnings);
    EXPECT_NE(deep.warnings[0].message.find(
                  cat("nested deeper than ", std::to_string(kMaxStyleSheetNesting))),
              std::string::npos)
        << deep.warnings[0].message;
    EXPECT_TRUE(near(square(deep, 0), kBlack, 1e-6f));
    // Each import reads its file: past kMaxStyleSheetFiles, one warning each.
    std::string many = "<style>";
    for (std::size_t i = 0; i < kMaxStyleSheetFiles + 3; ++i) many += "@import '30.css';";
    const Drawn wide = s.render("", many + "</style>" + kFour);
    ASSERT_EQ(wide.warnings.size(), 3u) << warnings_text(wide.warnings);
    EXPECT_NE(wide.warnings[0].message.find("more than 256 style sheet files"), std::string::npos)
        << wide.warnings[0].message;
    EXPECT_TRUE(near(square(wide, 0), kLime, 1e-6f));
}

// A sheet may import one elsewhere in the SVG's folder; an href's entity
// references are decoded (Associating Style Sheets, 3); a var() in a file
// works though the document's text has none.
TEST(LinkedStyleSheets, FilesStayWithinTheSvgsFolderAndHrefsAreDecoded) {
    const Sheets s;
    s.write("css/main.css", "@import '../common/x.css';");
    s.write("common/x.css", "#p { --c: #00ff00; fill: VAR(--c) }"); // any case
    s.write("a&b.css", ".x { fill: #00ff00 }");
    const Drawn d = s.render(R"(<?xml-stylesheet href="css/main.css"?>)"
                             R"(<?xml-stylesheet href="a&amp;b.css"?>)",
                             kFour);
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(square(d, 0), kLime, 1e-6f));
    EXPECT_TRUE(near(square(d, 1), kLime, 1e-6f));
}

// Every import of a large file reads it: its bytes count against what all
// sheets may hold (review: 255 imports of a 4.5 MB sheet took 56 s and
// 6.6 GB before).
TEST(LinkedStyleSheets, ImportedBytesCountAgainstOneSheetsLimit) {
    const Sheets s;
    s.write("big.css", "#p { fill: #00ff00 }" + std::string(4000, ' '));
    SvgOptions o;
    o.max_attribute_bytes = 10000; // two imports of big.css, not three
    const Drawn d = s.render("",
                             std::string("<style>@import 'big.css'; @import 'big.css';") +
                                 "@import 'big.css';</style>" + kFour,
                             o);
    ASSERT_EQ(d.warnings.size(), 1u) << warnings_text(d.warnings);
    EXPECT_NE(d.warnings[0].message.find("more than 10000 bytes of style sheet files"),
              std::string::npos)
        << d.warnings[0].message;
    EXPECT_TRUE(near(square(d, 0), kLime, 1e-6f));
}

} // namespace
} // namespace casteljau
