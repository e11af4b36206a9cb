// Compositing and whole-scene rendering, with values worked out by hand.
#include "casteljau/paint/canvas.h"
#include "casteljau/render/bands.h"
#include "casteljau/render/renderer.h"
#include "casteljau/svg/reader.h"
#include "pixels.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

TEST(Canvas, SourceOverWithCoverage) {
    Canvas c(4, 1);
    c.fill({0, 0, 1, 1}); // opaque blue
    const float cov[2] = {1.0f, 0.5f};
    c.composite_span({0, 1, 2, cov, 0}, premultiply({1, 0, 0, 1}, 0.5f)); // half-transparent red
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

TEST(Render, ShapeOpacityAppliesToFillAndStrokeTogether) {
    // Opaque red stroke over a blue fill, opacity 0.5 on the element: where the
    // stroke covers the fill, only red at 0.5 shows (through a layer), not red
    // over half-visible blue.
    const Canvas c =
        render(R"svg(<svg width="40" height="40"><rect x="10" y="10" width="20" height="20"
        fill="blue" stroke="red" stroke-width="6" opacity="0.5"/></svg>)svg");
    const Premul p = c.row(10)[20]; // on the stroke, over the fill's edge
    EXPECT_NEAR(p.r, 0.5f, 1e-6f);
    EXPECT_NEAR(p.b, 0.0f, 1e-6f);
    EXPECT_NEAR(p.a, 0.5f, 1e-6f);
    EXPECT_NEAR(c.row(20)[20].b, 0.5f, 1e-6f); // the fill alone inside
}

TEST(Render, NonUniformScalingStretchesTheStroke) {
    // A horizontal and a vertical line of width 2 under scale(1, 3): the
    // horizontal one becomes 6 px thick, the vertical one stays 2 px wide.
    const Canvas c = render(R"svg(<svg width="60" height="60"><g transform="scale(1 3)">
        <path d="M5 5 H55" stroke="black" stroke-width="2"/><path d="M30 8 V18" stroke="black" stroke-width="2"/>
        </g></svg>)svg");
    int thick = 0, wide = 0;
    for (int y = 0; y < 60; ++y) thick += c.row(y)[10].a > 0.5f;
    for (int x = 0; x < 60; ++x) wide += c.row(40)[x].a > 0.5f;
    EXPECT_EQ(thick, 6);
    EXPECT_EQ(wide, 2);
}

// Bands on several threads give the same bits as one thread and as one
// whole-frame render: edges are clipped to the frame, never to the band, and
// a band leaves out only the nodes that do not reach it; on scenes with
// layers and with shapes crossing band borders, for band counts that do not
// divide the height, and with the last bands taken in halves.
TEST(Render, BandsAreBitIdenticalToOneThread) {
    for (const char* file :
         {"dense.svg", "opacity.svg", "holes.svg", "transforms.svg", "strokes.svg"}) {
        const SvgResult doc = read_svg_file(std::string(CASTELJAU_EXAMPLES "/svg/") + file);
        ASSERT_TRUE(doc.scene) << doc.error;
        const int w = int(doc.scene->width * 1.5), h = int(doc.scene->height * 1.5);
        BandRenderer one, many;
        Canvas a(w, h), b(w, h);
        for (bool aa : {true, false}) {
            RenderOptions o;
            o.antialias = aa;
            a.reset(w, h); // transparent, as the bands clear it
            Renderer().render(*doc.scene, Affine::scale(1.5), a, o);
            b.fill({1, 0, 1, 1}); // no band may leave a row unvisited
            one.render(*doc.scene, Affine::scale(1.5), b, o, {0, 0, 0, 0}, 1);
            EXPECT_EQ(testing::differing_rows(a, b), 0)
                << file << ": bands against one whole frame, aa " << aa;
            for (int threads : {2, 3, 7}) {
                b.fill({1, 0, 1, 1});
                many.render(*doc.scene, Affine::scale(1.5), b, o, {0, 0, 0, 0}, threads);
                EXPECT_EQ(testing::differing_rows(a, b), 0)
                    << file << " with " << threads << " threads, aa " << aa;
            }
        }
    }
}

// Stage times cost clock reads per shape, so they are read only on request.
TEST(Render, StageTimesOnlyWhenAsked) {
    const SvgResult doc = read_svg_file(CASTELJAU_EXAMPLES "/svg/strokes.svg");
    ASSERT_TRUE(doc.scene) << doc.error;
    Canvas c(int(doc.scene->width), int(doc.scene->height));
    RenderOptions o;
    const RenderStats quiet = Renderer().render(*doc.scene, Affine::identity(), c, o);
    EXPECT_EQ(quiet.flatten_ms, 0.0);
    EXPECT_EQ(quiet.raster_ms, 0.0);
    o.time_stages = true;
    const RenderStats timed = Renderer().render(*doc.scene, Affine::identity(), c, o);
    EXPECT_GT(timed.flatten_ms, 0.0);
    EXPECT_GT(timed.raster_ms, 0.0);
    EXPECT_EQ(timed.flatten.segments_out, quiet.flatten.segments_out);
}

} // namespace
} // namespace casteljau
