// Compositing and whole-scene rendering, with values worked out by hand.
#include "casteljau/paint/canvas.h"
#include "casteljau/render/bands.h"
#include "casteljau/render/renderer.h"
#include "casteljau/svg/reader.h"

#include <cstring>
#include <gtest/gtest.h>

namespace casteljau {
namespace {

TEST(Canvas, SourceOverWithCoverage) {
    Canvas c(4, 1);
    c.fill({0, 0, 1, 1}); // opaque blue
    const float cov[2] = {1.0f, 0.5f};
    c.composite_span({0, 1, 2, cov}, premultiply({1, 0, 0, 1}, 0.5f)); // half-transparent red
    // Full coverage: 0.5 red over blue = (0.5, 0, 0.5, 1).
    EXPECT_FLOAT_EQ(c.row(0)[1].r, 0.5f);
    EXPECT_FLOAT_EQ(c.row(0)[1].b, 0.5f);
    EXPECT_FLOAT_EQ(c.row(0)[1].a, 1.0f);
    // Half coverage: effective alpha 0.25.
    EXPECT_FLOAT_EQ(c.row(0)[2].r, 0.25f);
    EXPECT_FLOAT_EQ(c.row(0)[2].b, 0.75f);
    EXPECT_FLOAT_EQ(c.row(0)[3].b, 1.0f); // untouched
}

TEST(Canvas, LayersCompositeAtTheirOriginWithOpacity) {
    Canvas parent(6, 6), layer(2, 2, 3, 4);
    layer.fill({0, 1, 0, 1});
    parent.composite_layer(layer, 0.25f);
    EXPECT_FLOAT_EQ(parent.row(4)[3].g, 0.25f);
    EXPECT_FLOAT_EQ(parent.row(5)[4].a, 0.25f);
    EXPECT_FLOAT_EQ(parent.row(3)[3].a, 0.0f);
    Canvas off(4, 4, 5, 5); // mostly outside the parent: clipped, no overrun
    off.fill({1, 1, 1, 1});
    parent.composite_layer(off, 1.0f);
    EXPECT_FLOAT_EQ(parent.row(5)[5].a, 1.0f);
}

Canvas render(const std::string& svg, double scale = 1, bool aa = true) {
    const SvgResult doc = parse_svg(svg, "t.svg");
    EXPECT_TRUE(doc.scene) << doc.error;
    Canvas c(int(doc.scene->width * scale), int(doc.scene->height * scale));
    Renderer r;
    RenderOptions o;
    o.antialias = aa;
    r.render(*doc.scene, Affine::scale(scale), c, o);
    return c;
}

TEST(Render, GroupOpacityDiffersFromPerShapeOpacityWhereShapesOverlap) {
    // Two opaque overlapping squares in a 0.5 group: the overlap is 0.5;
    // the same squares each at fill-opacity 0.5: the overlap is 0.75.
    const Canvas g = render(R"(<svg width="10" height="4"><g opacity="0.5">
        <rect width="6" height="4" fill="black"/><rect x="4" width="6" height="4" fill="black"/></g></svg>)");
    const Canvas s = render(R"(<svg width="10" height="4">
        <rect width="6" height="4" fill-opacity="0.5"/><rect x="4" width="6" height="4" fill-opacity="0.5"/></svg>)");
    EXPECT_FLOAT_EQ(g.row(1)[5].a, 0.5f);
    EXPECT_FLOAT_EQ(s.row(1)[5].a, 0.75f);
    EXPECT_FLOAT_EQ(g.row(1)[1].a, 0.5f);
    EXPECT_FLOAT_EQ(s.row(1)[1].a, 0.5f);
}

TEST(Render, ScaleAndViewBoxPlaceShapesExactly) {
    const Canvas c = render(
        R"(<svg width="8" height="8" viewBox="0 0 4 4"><rect x="1" y="1" width="2" height="1" fill="red"/></svg>)",
        2);
    // viewBox scale 2, render scale 2: the rect covers pixels [4, 12) x [4, 8).
    EXPECT_FLOAT_EQ(c.row(4)[4].r, 1.0f);
    EXPECT_FLOAT_EQ(c.row(7)[11].r, 1.0f);
    EXPECT_FLOAT_EQ(c.row(8)[8].a, 0.0f);
    EXPECT_FLOAT_EQ(c.row(5)[12].a, 0.0f);
}

TEST(Render, AliasedModeHasOnlyFullOrNoCoverage) {
    const Canvas c =
        render(R"(<svg width="20" height="20"><circle cx="10" cy="10" r="7.3"/></svg>)", 1, false);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) {
            const float a = c.row(y)[x].a;
            EXPECT_TRUE(a == 0.0f || a == 1.0f) << x << "," << y << ": " << a;
            const double dx = x + 0.5 - 10, dy = y + 0.5 - 10, d = std::sqrt(dx * dx + dy * dy);
            if (std::fabs(d - 7.3) > 0.3) {
                EXPECT_EQ(a, d < 7.3 ? 1.0f : 0.0f) << x << "," << y;
            }
        }
}

// Bands on several threads give the same bits as one thread: edges are
// clipped to the frame, never to the band, on scenes with layers and with
// shapes crossing band borders, for band counts that do not divide the height.
TEST(Render, BandsAreBitIdenticalToOneThread) {
    for (const char* file : {"dense.svg", "opacity.svg", "holes.svg", "transforms.svg"}) {
        const SvgResult doc = read_svg_file(std::string(CASTELJAU_EXAMPLES "/svg/") + file);
        ASSERT_TRUE(doc.scene) << doc.error;
        const int w = int(doc.scene->width * 1.5), h = int(doc.scene->height * 1.5);
        BandRenderer one, many;
        Canvas a(w, h), b(w, h);
        for (bool aa : {true, false}) {
            RenderOptions o;
            o.antialias = aa;
            one.render(*doc.scene, Affine::scale(1.5), a, o, {0, 0, 0, 0}, 1);
            for (int threads : {2, 3, 7}) {
                many.render(*doc.scene, Affine::scale(1.5), b, o, {0, 0, 0, 0}, threads);
                int differing = 0;
                for (int y = 0; y < h; ++y)
                    differing +=
                        std::memcmp(a.row(y), b.row(y), std::size_t(w) * sizeof(Premul)) != 0;
                EXPECT_EQ(differing, 0) << file << " with " << threads << " threads, aa " << aa;
            }
        }
    }
}

} // namespace
} // namespace casteljau
