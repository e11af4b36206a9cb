// CSS custom properties and var() (svg/custom_properties.h): substitution
// alone, then through the reader's cascade.
#include "casteljau/svg/custom_properties.h"
#include "casteljau/svg/reader.h"

#include <gtest/gtest.h>
#include <string>

namespace casteljau {
namespace {

TEST(Var, SubstitutesFallsBackAndRefusesWhatItCannot) {
    const CustomProperties custom = {{"--a", "red"},
                                     {"--b", "var(--a)"},
                                     {"--self", "var(--self)"},
                                     {"--x2", "var(--x1) var(--x1)"},
                                     {"--x1", "ab ab"}};
    const auto sub = [&](std::string_view v, std::size_t limit = 1000) {
        return substitute_vars(v, &custom, limit);
    };
    EXPECT_EQ(sub("var(--a)"), "red");
    EXPECT_EQ(sub("1px solid VAR( --b )"), "1px solid red") << "nested, any case";
    EXPECT_EQ(sub("var(--none, var(--a))"), "red") << "the fallback, itself substituted";
    EXPECT_EQ(sub("var(--none, rgb(1, 2, 3))"), "rgb(1, 2, 3)") << "commas inside the fallback";
    EXPECT_EQ(sub("myvar(--a) url('var(')"), "myvar(--a) url('var(')") << "no var() there";
    EXPECT_EQ(sub("var(--x2)"), "ab ab ab ab");
    EXPECT_EQ(sub("var(--x2)", 10), std::nullopt) << "past the size limit";
    EXPECT_EQ(sub("var(--none)"), std::nullopt);
    EXPECT_EQ(sub("var(--self)"), std::nullopt) << "a cycle";
    EXPECT_EQ(sub("var(a)"), std::nullopt) << "not a custom property's name";
    EXPECT_EQ(sub("var(--a"), std::nullopt) << "unclosed";
    EXPECT_EQ(substitute_vars("var(--a, blue)", nullptr, 100), "blue") << "none declared";
    EXPECT_TRUE(has_var(" Var(--a)"));
    EXPECT_FALSE(has_var("envar(--a)"));
}

TEST(Var, ThroughTheCascade) {
    const SvgResult r =
        parse_svg(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
        <style>:root { --main: #00f; --w: 20px } .c { fill: var(--main) }
          g { --main: lime }</style>
        <rect class="c" x="var(--w)" width="10" height="10"/>
        <g><rect class="c" style="width: var(--w); height: 10px"/></g>
        <rect style="--main: red; fill: var(--main); stroke: var(--gone)" width="5" height="5"/>
        <rect fill="var(--main)" width="5" height="5"/>
        </svg>)svg",
                  "t.svg");
    ASSERT_TRUE(r.scene) << r.error;
    std::vector<const Shape*> s;
    for (const Node& n : r.scene->root.children) s.push_back(&std::get<Shape>(n.item));
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s[0]->fill->color, (Rgba{0, 0, 1, 1})) << ":root's, inherited";
    EXPECT_EQ(s[0]->path.bounds().x0, 0) << "x is an attribute here: no var()";
    EXPECT_EQ(s[1]->fill->color, (Rgba{0, 1, 0, 1})) << "the group's own";
    EXPECT_EQ(s[1]->path.bounds().width(), 20) << "a geometry property in CSS";
    EXPECT_EQ(s[2]->fill->color, (Rgba{1, 0, 0, 1})) << "its own, in the same declarations";
    EXPECT_FALSE(s[2]->stroke) << "an undefined var(): ignored";
    EXPECT_EQ(s[3]->fill->color, (Rgba{0, 0, 0, 1})) << "an attribute takes no var()";
    ASSERT_GE(r.warnings.size(), 1u);
    bool told = false;
    for (const SvgDiagnostic& w : r.warnings)
        told = told || w.text().find("property stroke: 'var(--gone)'") != std::string::npos;
    EXPECT_TRUE(told);
}

} // namespace
} // namespace casteljau
