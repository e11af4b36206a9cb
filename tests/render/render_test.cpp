// Compositing and whole-scene rendering, with values worked out by hand.
#include "casteljau/paint/canvas.h"
#include "casteljau/render/bands.h"
#include "casteljau/render/renderer.h"
#include "casteljau/svg/reader.h"
#include "corpus.h"
#include "pixels.h"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>
#include <vector>

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

// A layer holds all that is drawn into it: group opacity of 0.999 over a
// shape of one paint draws what the shape at 0.999 opacity draws without a
// layer, for random fills and strokes (wide, mitred, capped, dashed; lines
// with no height). The layer once took the paths' tight bounds: strokes lost
// their outer half, and a horizontal line's stroke became a hairline.
TEST(Render, AGroupLayerHoldsEverythingItsShapesDraw) {
    testing::Rng rng(21);
    const LineCap caps[] = {LineCap::Butt, LineCap::Round, LineCap::Square};
    const LineJoin joins[] = {LineJoin::Miter, LineJoin::Round, LineJoin::Bevel};
    for (int trial = 0; trial < 60; ++trial) {
        Shape s;
        if (trial % 3 == 2) { // a horizontal or vertical line: no area at all
            const Point a{rng.uniform(10, 50), rng.uniform(10, 50)};
            s.path.move_to(a);
            s.path.line_to(trial % 2 ? Point{rng.uniform(60, 90), a.y}
                                     : Point{a.x, rng.uniform(60, 90)});
        } else {
            s.path = testing::random_blob(rng, 60, 4);
        }
        s.transform = Affine::translate({20, 20});
        const Rgba color{float(rng.uniform(0, 1)), float(rng.uniform(0, 1)),
                         float(rng.uniform(0, 1)), 1};
        if (trial % 3 == 0) {
            s.fill = Fill{color, nullptr, 1, FillRule::NonZero};
        } else {
            StrokeGeometry g;
            g.width = rng.uniform(1, 24);
            g.cap = caps[trial % 3];
            g.join = joins[(trial / 3) % 3];
            g.miter_limit = rng.uniform(1, 10);
            if (trial % 5 == 0) g.dashes = {rng.uniform(2, 9), rng.uniform(2, 9)};
            s.stroke = Stroke{color, nullptr, 1, g};
        }
        Scene layered, direct;
        layered.width = direct.width = 120;
        layered.height = direct.height = 120;
        layered.root.children.push_back(Node{Group{0.999f, {Node{s}}}});
        s.opacity = 0.999f;
        direct.root.children.push_back(Node{s});
        Canvas a(120, 120), b(120, 120);
        Renderer r;
        r.render(layered, Affine::identity(), a, {});
        r.render(direct, Affine::identity(), b, {});
        float worst = 0;
        for (int y = 0; y < 120; ++y)
            for (int x = 0; x < 120; ++x)
                worst = std::max(worst, std::fabs(a.row(y)[x].a - b.row(y)[x].a));
        EXPECT_LT(worst, 1e-5f) << "trial " << trial << ", bounds " << s.path.bounds().x0 << " "
                                << s.path.bounds().y0 << " " << s.path.bounds().x1 << " "
                                << s.path.bounds().y1;
    }
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
template <class Canvas>
class RenderFormats : public ::testing::Test {};
using CanvasFormats = ::testing::Types<Canvas, Canvas8>;
TYPED_TEST_SUITE(RenderFormats, CanvasFormats);

TYPED_TEST(RenderFormats, BandsAreBitIdenticalToOneThread) {
    for (const char* file :
         {"dense.svg", "opacity.svg", "holes.svg", "transforms.svg", "strokes.svg"}) {
        const SvgResult doc = read_svg_file(std::string(CASTELJAU_EXAMPLES "/svg/") + file);
        ASSERT_TRUE(doc.scene) << doc.error;
        const int w = int(doc.scene->width * 1.5), h = int(doc.scene->height * 1.5);
        BandRenderer one, many;
        TypeParam a(w, h), b(w, h);
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

// A render onto a Canvas8 is the float render rounded composite by
// composite: each rounds once, to within half a step (paint/pixel8.h), and a
// step's error is carried on scaled by at most 1, so a pixel is within half
// a step per composite reaching it (a fill, a stroke, a group's layer) of
// 255 times the float pixel. Rounding to nearest is also unbiased: the mean
// signed error over the covered pixels is near 0 (truncating would pull it
// towards -1/2 a composite).
TEST(Render, Canvas8IsTheFloatRenderRoundedPerComposite) {
    testing::Rng rng(77);
    constexpr int kSize = 96, kDiscs = 12, kGrouped = 4; // the last kGrouped are in a group
    struct Disc {
        double x, y, reach;
    };
    std::vector<Disc> discs;
    std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' width='96' height='96'>";
    const auto hex = [&] {
        char b[8];
        std::snprintf(b, sizeof b, "#%02x%02x%02x", rng.integer(0, 255), rng.integer(0, 255),
                      rng.integer(0, 255));
        return std::string(b);
    };
    for (int i = 0; i < kDiscs; ++i) {
        if (i == kDiscs - kGrouped) svg += "<g opacity='0.6'>";
        const double x = rng.uniform(10, 86), y = rng.uniform(10, 86), r = rng.uniform(4, 30);
        const double sw = rng.uniform(0.5, 6);
        discs.push_back({x, y, r + sw / 2 + 1.5});
        svg += "<circle cx='" + std::to_string(x) + "' cy='" + std::to_string(y) + "' r='" +
               std::to_string(r) + "' fill='" + hex() + "' fill-opacity='" +
               std::to_string(rng.uniform(0.2, 1)) + "' stroke='" + hex() + "' stroke-width='" +
               std::to_string(sw) + "' stroke-opacity='" + std::to_string(rng.uniform(0.2, 1)) +
               "'/>";
    }
    svg += "</g></svg>";
    const SvgResult doc = parse_svg(svg, "discs.svg");
    ASSERT_TRUE(doc.scene) << doc.error;
    Canvas exact(kSize, kSize);
    Canvas8 bytes(kSize, kSize);
    Renderer().render(*doc.scene, Affine::identity(), exact, {});
    Renderer().render(*doc.scene, Affine::identity(), bytes, {});
    double signed_sum = 0;
    long covered = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            int composites = 0;
            bool in_group = false;
            for (int i = 0; i < kDiscs; ++i) {
                const Disc& d = discs[std::size_t(i)];
                if (std::hypot(x + 0.5 - d.x, y + 0.5 - d.y) > d.reach) continue;
                composites += 2; // fill and stroke
                in_group |= i >= kDiscs - kGrouped;
            }
            composites += in_group; // the layer onto the canvas
            const Premul8 got = bytes.row(y)[x];
            const Premul want = exact.row(y)[x];
            const float errors[4] = {got.r - 255 * want.r, got.g - 255 * want.g,
                                     got.b - 255 * want.b, got.a - 255 * want.a};
            for (float e : errors) {
                ASSERT_LE(std::fabs(e), 0.5 * composites + 1e-3)
                    << "at " << x << "," << y << " after " << composites << " composites";
                if (composites > 0) signed_sum += e, ++covered;
            }
        }
    ASSERT_GT(covered, 4 * kSize * kSize / 2);
    EXPECT_LT(std::fabs(signed_sum / double(covered)), 0.1) << "the rounding is biased";
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
