// Partial re-render: a tile of the frame, and a Drawing redrawn after edits
// only where they damaged it, must equal a full render pixel for pixel.
#include "casteljau/render/drawing.h"
#include "casteljau/svg/reader.h"
#include "casteljau/svg/shapes.h"
#include "corpus.h"
#include "pixels.h"

#include <algorithm>
#include <gtest/gtest.h>

namespace casteljau {
namespace {

using testing::differing_rows;
using testing::Rng;

constexpr Premul kBackground{0.5f, 0.25f, 0.0f, 0.5f};

PixelRect random_rect(Rng& rng, int w, int h) {
    const int x0 = rng.integer(-10, w - 1), y0 = rng.integer(-10, h - 1);
    return {x0, y0, x0 + rng.integer(1, w / 2), y0 + rng.integer(1, h / 2)};
}

TEST(PartialRender, TileEqualsFullRenderOnTheExamples) {
    // Layers (opacity.svg), gradients, dashes and joins (strokes.svg), holes
    // and even-odd: every tile, wherever its edges fall, bit for bit.
    Rng rng(6);
    // And every kind of layer: clips, masks, blend modes, patterns, images.
    for (const std::string file :
         {"dense.svg", "opacity.svg", "holes.svg", "transforms.svg", "strokes.svg", "gradients.svg",
          "stars.svg", "curves.svg", "@clip_paths.svg", "@masks.svg", "@patterns.svg",
          "@blend_modes.svg", "@images.svg"}) {
        const SvgResult doc = read_svg_file(
            file[0] == '@' ? std::string(CASTELJAU_TESTS "/svg/agreement/") + file.substr(1)
                           : std::string(CASTELJAU_EXAMPLES "/svg/") + file);
        ASSERT_TRUE(doc.scene) << doc.error;
        const Affine view = Affine::scale(1.25);
        const int w = int(doc.scene->width * 1.25), h = int(doc.scene->height * 1.25);
        Canvas full(w, h);
        BandRenderer bands;
        bands.render(*doc.scene, view, full, {}, kBackground, 1);
        Renderer renderer;
        Canvas tile;
        for (int i = 0; i < 12; ++i) {
            PixelRect r = random_rect(rng, w, h);
            r = {std::max(r.x0, 0), std::max(r.y0, 0), std::min(r.x1, w), std::min(r.y1, h)};
            if (r.width() <= 0 || r.height() <= 0) continue;
            tile.reset(r.width(), r.height(), r.x0, r.y0, kBackground);
            renderer.render(*doc.scene, view, tile, {}, {0, 0, w, h});
            EXPECT_EQ(differing_rows(full, tile), 0)
                << file << " tile " << r.x0 << "," << r.y0 << " " << r.width() << "x" << r.height();
        }
    }
}

Shape random_shape(Rng& rng, double extent) {
    Shape s;
    const Vec2 at{rng.uniform(-20, extent), rng.uniform(-20, extent)};
    // Drawn in order: function arguments are evaluated in an unspecified
    // order (GCC right to left, clang left to right), which gave the two
    // compilers different shapes.
    const double radius = rng.uniform(5, 80);
    const int lobes = rng.integer(1, 5);
    s.path = testing::random_blob(rng, radius, lobes);
    s.transform = Affine::translate(at) * Affine::rotate(rng.uniform(0, 6.28));
    const Rgba color{float(rng.uniform(0, 1)), float(rng.uniform(0, 1)), float(rng.uniform(0, 1)),
                     float(rng.uniform(0.3, 1))};
    const int kind = rng.integer(0, 3);
    if (kind != 1) {
        s.fill = Fill{color, nullptr, 1, rng.integer(0, 1) ? FillRule::EvenOdd : FillRule::NonZero};
        if (rng.integer(0, 3) == 0) {
            auto g = std::make_shared<Gradient>();
            g->stops = {{0, color}, {1, Rgba{0, 0, 1, 1}}};
            s.fill->gradient = g;
        }
    }
    if (kind != 0) {
        Stroke st{color, nullptr, 1, {}};
        st.geometry.width = rng.log_uniform(0.3, 12);
        st.geometry.join = LineJoin(rng.integer(0, 2));
        st.geometry.cap = LineCap(rng.integer(0, 2));
        if (rng.integer(0, 2) == 0) st.geometry.dashes = {rng.uniform(1, 10), rng.uniform(1, 10)};
        s.stroke = st;
    }
    if (kind == 2 && rng.integer(0, 1)) s.opacity = 0.6f; // fill and stroke: a layer
    return s;
}

template <class Canvas>
class PartialRenderFormats : public ::testing::Test {};
using CanvasFormats = ::testing::Types<Canvas, Canvas8>;
TYPED_TEST_SUITE(PartialRenderFormats, CanvasFormats);

TYPED_TEST(PartialRenderFormats, RedrawingTheDamageAfterEditsEqualsAFullRender) {
    Rng rng(12);
    const int w = 300, h = 280; // two and a bit bands of 128 rows
    Drawing drawing(w, h);
    for (int i = 0; i < 150; ++i) drawing.add(random_shape(rng, w));
    TypeParam edited(w, h), reference(w, h);
    drawing.render(edited, kBackground);
    for (int edit = 0; edit < 40; ++edit) {
        const Drawing::ShapeId id = std::size_t(rng.integer(0, int(drawing.size()) - 1));
        const PixelRect damage =
            rng.integer(0, 4) == 0 ? drawing.remove(id) : drawing.replace(id, random_shape(rng, w));
        drawing.render_region(edited, damage, kBackground);
        drawing.render(reference, kBackground, {}, 2);
        ASSERT_EQ(differing_rows(reference, edited), 0)
            << "edit " << edit << " of shape " << id << ", damage " << damage.x0 << "," << damage.y0
            << " " << damage.width() << "x" << damage.height();
    }
}

TEST(PartialRender, ASmallRegionFlattensOnlyTheShapesCrossingIt) {
    // A 40 x 40 grid of small discs: a 10 x 10 px region meets at most four.
    Drawing drawing(400, 400);
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            Path p;
            p.move_to({i * 10.0 + 8, j * 10.0 + 5});
            p.arc_to({3, 3}, 0, true, true, {i * 10.0 + 2, j * 10.0 + 5});
            p.arc_to({3, 3}, 0, true, true, {i * 10.0 + 8, j * 10.0 + 5});
            p.close();
            drawing.fill(p, Paint::solid({0, 0, 0, 1}));
        }
    Canvas c(400, 400);
    const RenderStats full = drawing.render(c, {});
    const RenderStats part = drawing.render_region(c, {101, 101, 109, 109}, {});
    EXPECT_GT(full.flatten.curves_in, 1000u);
    EXPECT_GT(part.flatten.curves_in, 0u);
    EXPECT_LE(part.flatten.curves_in * 1600, full.flatten.curves_in * 4)
        << "part " << part.flatten.curves_in << " full " << full.flatten.curves_in;
}

TEST(DrawingLayers, ClippedBlendedGroupsImagesAndPatternsRedrawExactly) {
    // The application API's clips, blend modes, images and patterns: a
    // partial redraw after editing them equals a full render, bit for bit,
    // and each does what it says at a pixel.
    Drawing d(120, 90);
    auto image = std::make_shared<RasterImage>();
    image->width = 2;
    image->height = 1;
    image->pixels = {{1, 0, 0, 1}, {0, 0, 1, 1}};
    const Drawing::ShapeId pic = d.image(image, {10, 10, 50, 30}, Affine::identity(), false);
    Pattern checks;
    checks.width = checks.height = 8;
    Shape quarter;
    quarter.path = rect_path(0, 0, 4, 4, 0, 0);
    quarter.fill = Fill{{0, 0.5f, 0, 1}, nullptr, 1, FillRule::NonZero};
    checks.content.children.push_back(Node{quarter});
    d.fill(rect_path(60, 10, 50, 30, 0, 0), Paint::tiled(checks));
    Group g;
    g.clip = clip_of(rect_path(20, 50, 40, 30, 0, 0));
    g.blend = BlendMode::Difference;
    Shape disc;
    disc.path = rect_path(10, 45, 60, 40, 0, 0);
    disc.fill = Fill{{1, 1, 1, 1}, nullptr, 1, FillRule::NonZero};
    g.children.push_back(Node{disc});
    const Drawing::ShapeId group = d.add(g);
    Canvas full(120, 90), edited(120, 90);
    d.render(edited, kBackground);
    EXPECT_EQ(edited.row(20)[15].r, 1.0f) << "the image's left pixel, nearest";
    EXPECT_EQ(edited.row(20)[45].b, 1.0f) << "its right pixel";
    EXPECT_NEAR(edited.row(17)[65].g, 0.5f, 1e-6f) << "a pattern tile's painted quarter";
    EXPECT_EQ(edited.row(13)[61].g, kBackground.g) << "its unpainted part";
    EXPECT_NEAR(edited.row(60)[30].r, 0.5f, 1e-6f) << "white difference over the background";
    EXPECT_EQ(edited.row(60)[15].r, kBackground.r) << "outside the group's clip";
    EXPECT_FALSE(d.shape_at({30, 60}).has_value()) << "hit tests pass over groups";
    // Edits: the group moved, the image replaced; redraw only the damage.
    Group moved = g;
    moved.clip = clip_of(rect_path(40, 50, 60, 35, 0, 0));
    PixelRect dirty = d.replace(group, Node{moved});
    d.render_region(edited, dirty, kBackground);
    dirty = d.replace(pic, Node{Shape{}});
    d.render_region(edited, dirty, kBackground);
    d.render(full, kBackground);
    EXPECT_EQ(differing_rows(full, edited), 0);
}

TEST(DrawingLayers, FilteredGroupsRedrawExactly) {
    // A drop shadow and a blur on groups: a partial redraw after moving one
    // equals a full render, bit for bit (the damage is the filter region).
    Drawing d(160, 120);
    Group card;
    Shape s;
    s.path = rect_path(20, 20, 50, 40, 0, 0);
    s.fill = Fill{{0.2f, 0.4f, 0.8f, 1}, nullptr, 1, FillRule::NonZero};
    card.children.push_back(Node{s});
    card.filters.push_back(drop_shadow_filter({4, 6}, 3, {0, 0, 0, 0.5f}, {0, 0, 100, 90}));
    const Drawing::ShapeId shadowed = d.add(card);
    Group soft = card;
    soft.filters = {blur_filter(2.5, {80, 10, 150, 110})};
    soft.children[0] = Node{Shape{rect_path(95, 30, 40, 60, 0, 0), {}, s.fill, {}}};
    d.add(soft);
    Canvas full(160, 120), edited(160, 120);
    d.render(edited, kBackground);
    EXPECT_EQ(edited.row(40)[40].b, 0.8f) << "the card over its shadow";
    EXPECT_LT(edited.row(63)[50].r, kBackground.r - 0.1f) << "the shadow below it";
    EXPECT_LT(edited.row(60)[95].b, 0.8f) << "the blurred edge";
    EXPECT_GT(edited.row(60)[95].b, kBackground.b) << "...spread beyond the shape";
    Group moved = card;
    moved.children[0] = Node{Shape{rect_path(10, 50, 50, 40, 0, 0), {}, s.fill, {}}};
    const PixelRect dirty = d.replace(shadowed, Node{moved});
    d.render_region(edited, dirty, kBackground);
    d.render(full, kBackground);
    EXPECT_EQ(differing_rows(full, edited), 0);
}

TEST(DrawingHit, ShapeAtFindsTheTopmostFillOrStroke) {
    Drawing d(200, 200);
    Path square;
    square.move_to({0, 0});
    square.line_to({100, 0});
    square.line_to({100, 100});
    square.line_to({0, 100});
    square.close();
    const auto below = d.fill(square, Paint::solid({1, 0, 0, 1}), Affine::translate({10, 10}));
    // A circle of radius 40 around (110, 110), scaled 2x from radius 20.
    Path circle;
    circle.move_to({20, 0});
    circle.arc_to({20, 20}, 0, true, true, {-20, 0});
    circle.arc_to({20, 20}, 0, true, true, {20, 0});
    circle.close();
    const auto above = d.fill(circle, Paint::solid({0, 0, 1, 1}),
                              Affine::translate({110, 110}) * Affine::scale(2));
    StrokeGeometry g;
    g.width = 2;
    Path line;
    line.move_to({150, 20});
    line.line_to({190, 20});
    const auto stroked = d.stroke(line, Paint::solid({0, 0, 0, 1}), g);
    EXPECT_EQ(d.shape_at({20, 20}), below);
    EXPECT_EQ(d.shape_at({105, 105}), above);          // both cover it: the later one
    EXPECT_EQ(d.shape_at({110, 110 + 39.999}), above); // exact on the arc
    EXPECT_EQ(d.shape_at({110 + 35, 110 + 35}), std::nullopt);
    EXPECT_EQ(d.shape_at({170, 21.4}), stroked); // 0.4 px outside the 1 px half width
    EXPECT_EQ(d.shape_at({170, 22}), std::nullopt);
    EXPECT_EQ(d.shape_at({195, 195}), std::nullopt);
    d.remove(above);
    EXPECT_EQ(d.shape_at({105, 105}), below);
}

// Regression: a stroke drawn at scale 0, or so small that the scale's squares
// underflow to 0, asked the stroker for an outline at an infinite tolerance
// (0.01 px over a scale of 0), on which it never ended.
TEST(DrawingHit, AStrokeDrawnAtScaleZeroIsNeverHit) {
    Drawing d(100, 100);
    Path curve;
    curve.move_to({0, 0});
    curve.cubic_to({10, 20}, {30, -20}, {40, 0});
    StrokeGeometry g;
    g.width = 4;
    d.stroke(curve, Paint::solid({0, 0, 0, 1}), g, Affine::scale(0, 0));
    d.stroke(curve, Paint::solid({0, 0, 0, 1}), g, Affine::scale(1e-170));
    EXPECT_EQ(d.shape_at({0, 0}), std::nullopt);
    EXPECT_TRUE(d.shapes_in({-1, -1, 1, 1}).empty());
}

TEST(DrawingHit, ShapesInSelectsWhatTheRubberBandTouches) {
    Drawing d(300, 300);
    Rng rng(31);
    for (int i = 0; i < 60; ++i) d.add(random_shape(rng, 260));
    const Rect band{100, 120, 140, 170};
    const std::vector<Drawing::ShapeId> hits = d.shapes_in(band);
    EXPECT_FALSE(hits.empty());
    // No unselected shape draws on a pixel inside the band; every selected
    // one draws inside it, grown by a pixel (it may just touch the band).
    const auto coverage = [](const Canvas& c, int x0, int y0, int x1, int y1) {
        float sum = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) sum += c.row(y)[x].a;
        return sum;
    };
    int drawn_and_selected = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        Drawing one(300, 300);
        one.add(d.shape(i));
        Canvas c(300, 300);
        one.render(c, {});
        const bool selected = std::find(hits.begin(), hits.end(), i) != hits.end();
        if (!selected) {
            EXPECT_EQ(coverage(c, 100, 120, 140, 170), 0.0f) << "shape " << i;
        } else {
            // A fill of zero area (random_blob's one-lobe outline goes out
            // and back along one curve) is selected where its outline meets
            // the band, and draws nothing anywhere.
            if (coverage(c, 0, 0, 300, 300) == 0.0f) continue;
            EXPECT_GT(coverage(c, 99, 119, 141, 171), 0.0f) << "shape " << i;
            ++drawn_and_selected;
        }
    }
    EXPECT_GT(drawn_and_selected, 0); // the selected side was tested at all
    EXPECT_LT(hits.size(), d.size());
}

} // namespace
} // namespace casteljau
