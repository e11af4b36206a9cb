// The rasterizer's stages, each on its own, then together against a
// 256 x 256-supersampled reference.
#include "casteljau/curve/path_data.h"
#include "casteljau/raster/path_edges.h"
#include "casteljau/raster/rasterizer.h"
#include "corpus.h"
#include "coverage.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace casteljau {
namespace {

using testing::Polygon;

testing::CoverageImage rasterize(const std::vector<Polygon>& polys, FillRule rule, int w, int h,
                                 bool aa = true) {
    EdgeList edges;
    edges.reset(w, h);
    for (const Polygon& p : polys)
        for (std::size_t i = 0; i < p.size(); ++i) edges.add_line(p[i], p[(i + 1) % p.size()]);
    testing::CoverageImage img(w, h);
    Rasterizer r;
    r.fill(edges, rule, aa, img);
    EXPECT_TRUE(img.order_ok());
    return img;
}

// Largest difference, with the pixel where it happens, for diagnostics.
struct Diff {
    float max = 0;
    int x = 0, y = 0;
};
Diff compare(const testing::CoverageImage& img, const std::vector<float>& ref, int w) {
    Diff d;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        const float e = std::fabs(img.data()[i] - ref[i]);
        if (e > d.max) d = {e, int(i) % w, int(i) / w};
    }
    return d;
}

Polygon random_star(testing::Rng& rng, Point c, double r, int n) {
    Polygon p;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * (i + rng.uniform(0, 0.9)) / n;
        const double rr = r * rng.uniform(0.2, 1.0);
        p.push_back(c + Vec2{std::cos(a), std::sin(a)} * rr);
    }
    return p;
}

TEST(CoverageRow, DepositsSumToTheSignedHeight) {
    // Whatever the slope, the accumulated cover after the last column equals
    // dir * height: the row's running sum returns to the full coverage.
    testing::Rng rng(81);
    for (int i = 0; i < 1000; ++i) {
        CoverageRow row;
        row.reset(40);
        const float xa = float(rng.uniform(0, 40)), xb = float(rng.uniform(0, 40));
        const float ya = float(rng.uniform(0, 0.5)), yb = float(rng.uniform(0.5, 1));
        row.add_segment(xa, ya, xb, yb, -1.0f);
        float s = 0;
        for (int k = 0; k < 43; ++k) s += row.data()[k];
        EXPECT_NEAR(s, -(yb - ya), 1e-5f) << i;
        EXPECT_GE(row.begin(), int(std::min(xa, xb)));
        EXPECT_LE(row.end(), 43);
    }
}

TEST(CoverageRow, AVerticalEdgeSplitsItsPixelByArea) {
    CoverageRow row;
    row.reset(8);
    row.add_segment(3.25f, 0, 3.25f, 1, 1.0f);
    EXPECT_FLOAT_EQ(row.data()[3], 0.75f);
    EXPECT_FLOAT_EQ(row.data()[4], 0.25f);
}

TEST(Sweep, FillRules) {
    EXPECT_FLOAT_EQ(apply_fill_rule(-2.0f, FillRule::NonZero), 1.0f);
    EXPECT_FLOAT_EQ(apply_fill_rule(0.25f, FillRule::NonZero), 0.25f);
    EXPECT_FLOAT_EQ(apply_fill_rule(2.0f, FillRule::EvenOdd), 0.0f);
    EXPECT_FLOAT_EQ(apply_fill_rule(-1.25f, FillRule::EvenOdd), 0.75f);
    EXPECT_FLOAT_EQ(apply_fill_rule(3.0f, FillRule::EvenOdd), 1.0f);
}

// The spans of a swept row, each with a copy of its per-pixel coverage
// (empty for a solid span): the sweep's buffer is valid only during the
// call, so a recorded span's `coverage` is only compared with null.
struct RecordedRow final : SpanSink {
    std::vector<Span> spans;
    std::vector<std::vector<float>> coverage;
    void span(const Span& s) override {
        spans.push_back(s);
        coverage.emplace_back(s.coverage ? s.coverage : nullptr,
                              s.coverage ? s.coverage + s.len : nullptr);
    }
    // The coverage of every pixel of every span, summed.
    float total() const {
        float t = 0;
        for (std::size_t k = 0; k < spans.size(); ++k) {
            if (!spans[k].coverage) t += spans[k].solid * float(spans[k].len);
            for (float v : coverage[k]) t += v;
        }
        return t;
    }
};

// Sweeps row y of a `width`-pixel row (column i at pixel x_offset + i) holding
// vertical edges over the row's whole height, given as (x, direction), and
// checks that the sweep left the row zeroed.
RecordedRow sweep_vertical_edges(int width, int y, int x_offset,
                                 std::initializer_list<std::pair<float, float>> edges) {
    CoverageRow row;
    row.reset(width);
    for (const auto& [x, dir] : edges) row.add_segment(x, 0, x, 1, dir);
    RecordedRow sink;
    std::vector<float> scratch;
    sweep_row(row, y, x_offset, FillRule::NonZero, scratch, sink);
    for (const Span& s : sink.spans) EXPECT_EQ(s.y, y);
    for (int i = 0; i < width + 3; ++i) EXPECT_EQ(row.data()[i], 0.0f) << "row left dirty at " << i;
    return sink;
}

// The inside of a wide shape reaches the compositor as one solid span; the
// partly covered ends as per-pixel spans; no span is empty or overlaps.
TEST(Sweep, WideInsidesLeaveAsOneSolidSpan) {
    // A band from x = 3.5 to 200.25 over the whole row height, and a thin
    // sliver from x = 250 to 256 (short: per-pixel).
    const RecordedRow sink = sweep_vertical_edges(
        300, 7, 10, {{3.5f, -1.0f}, {200.25f, 1.0f}, {250.0f, -1.0f}, {256.0f, 1.0f}});
    ASSERT_EQ(sink.spans.size(), 4u);
    EXPECT_EQ(sink.spans[0].x, 13);
    EXPECT_EQ(sink.spans[0].len, 1);
    EXPECT_FLOAT_EQ(sink.coverage[0].at(0), 0.5f);
    EXPECT_EQ(sink.spans[1].coverage, nullptr);
    EXPECT_EQ(sink.spans[1].x, 14);
    EXPECT_EQ(sink.spans[1].len, 196);
    EXPECT_EQ(sink.spans[1].solid, 1.0f);
    EXPECT_EQ(sink.spans[2].x, 210);
    EXPECT_FLOAT_EQ(sink.coverage[2].at(0), 0.25f);
    EXPECT_EQ(sink.spans[3].x, 260);
    EXPECT_EQ(sink.spans[3].len, 6);
    EXPECT_EQ(sink.coverage[3].size(), 6u);
    EXPECT_NEAR(sink.total(), 200.25f - 3.5f + 6.0f, 1e-4f);
}

// Regression (the full-canvas rectangle): edges on column borders deposit an
// exact 0 in the column after them, which must not cut the row's inside
// into a one-pixel span and a solid one (the span wrote its row, the solid
// store wrote it again).
TEST(Sweep, PixelAlignedRowsLeaveAsOneSolidSpan) {
    const RecordedRow sink = sweep_vertical_edges(100, 3, 0, {{0.0f, -1.0f}, {100.0f, 1.0f}});
    ASSERT_EQ(sink.spans.size(), 1u);
    EXPECT_EQ(sink.spans[0].x, 0);
    EXPECT_EQ(sink.spans[0].len, 100);
    EXPECT_EQ(sink.spans[0].coverage, nullptr);
    EXPECT_EQ(sink.spans[0].solid, 1.0f);
}

// Fast against reference: whether the touched columns are few (summed in
// one pass) or spread (visited by their marks), every pixel carries the
// plain running sum of the row's deposits under the fill rule, bit for bit,
// the invisible ones are left out, and the row is left zeroed.
TEST(Sweep, SpansCarryTheRunningSumsExactly) {
    struct Record final : SpanSink {
        std::vector<float> cov = std::vector<float>(200, 0.0f);
        void span(const Span& s) override {
            for (int i = 0; i < s.len; ++i) {
                EXPECT_EQ(cov[std::size_t(s.x + i)], 0.0f) << "pixel " << s.x + i << " twice";
                cov[std::size_t(s.x + i)] = s.at(i);
            }
        }
    };
    testing::Rng rng(83);
    for (int i = 0; i < 2000; ++i) {
        const int spread = i % 2 ? rng.integer(2, 15) : rng.integer(16, 190);
        const float x0 = float(rng.uniform(0, 195 - spread));
        const FillRule rule = i % 4 < 2 ? FillRule::NonZero : FillRule::EvenOdd;
        CoverageRow row;
        row.reset(200);
        for (int k = rng.integer(1, 4); k > 0; --k) {
            const float xa = x0 + float(rng.uniform(0, spread)),
                        xb = x0 + float(rng.uniform(0, spread));
            row.add_segment(xa, 0, xb, 1, 1.0f); // down, then back up elsewhere: closed
            row.add_segment(x0 + float(rng.uniform(0, spread)), 0, xa, 1, -1.0f);
        }
        std::vector<float> deposits(row.data(), row.data() + 203);
        const int touched_end = row.end(); // past it, the winding is rounded (sweep.cpp)
        Record sink;
        std::vector<float> scratch;
        sweep_row(row, 0, 0, rule, scratch, sink);
        float s = 0;
        for (int x = 0; x < 200; ++x) {
            s += deposits[std::size_t(x)];
            const float want = apply_fill_rule(x < touched_end ? s : std::nearbyint(s), rule);
            EXPECT_EQ(sink.cov[std::size_t(x)], want < 1e-6f ? 0.0f : want)
                << "case " << i << " spread " << spread << " pixel " << x;
        }
        for (int x = 0; x < 203; ++x) EXPECT_EQ(row.data()[x], 0.0f) << "row left dirty at " << x;
    }
}

TEST(EdgeList, ClipsToTheCanvasKeepingWindingAtTheLeftBorder) {
    EdgeList e;
    e.reset(10, 10);
    e.add_line({-5, -5}, {15, 15}); // crosses the canvas diagonally, starting above-left
    e.add_line({3, 2}, {7, 2});     // horizontal: dropped
    e.add_line({-4, 1}, {-2, 9});   // left of the canvas: projected on x = 0
    e.add_line({12, 1}, {14, 9});   // right: projected on x = 10
    for (const Edge& x : e.edges()) {
        EXPECT_GE(x.y0, 0.0f);
        EXPECT_LE(x.y1, 10.0f);
        EXPECT_LT(x.y0, x.y1);
        EXPECT_GE(std::min(x.x0, x.x1), 0.0f);
        EXPECT_LE(std::max(x.x0, x.x1), 10.0f);
    }
    float left_height = 0;
    for (const Edge& x : e.edges())
        if (x.x0 == 0 && x.x1 == 0) left_height += x.y1 - x.y0;
    EXPECT_FLOAT_EQ(left_height, 8.0f);
}

TEST(Rasterizer, RandomPolygonsMatchTheSupersampledReference) {
    testing::Rng rng(82);
    const int w = 48, h = 40;
    for (int i = 0; i < 40; ++i) {
        const std::vector<Polygon> polys = {
            random_star(rng, rng.point(48), rng.uniform(3, 30), rng.integer(3, 12))};
        for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
            const auto img = rasterize(polys, rule, w, h);
            const Diff d = compare(img, testing::supersampled_coverage(polys, rule, w, h), w);
            EXPECT_LE(d.max, 1.0f / 255) << "polygon " << i << " at (" << d.x << ", " << d.y << ")";
        }
    }
}

TEST(Rasterizer, CirclesMatchTheSupersampledReference) {
    testing::Rng rng(83);
    const int w = 40, h = 40;
    for (int i = 0; i < 20; ++i) {
        const Point c = rng.point(40);
        const double r = rng.uniform(0.3, 25);
        Polygon p; // 0.001 px tolerance polygon of the circle: the same shape for both
        const int n = int(std::ceil(std::numbers::pi / std::acos(1 - 0.001 / r)));
        for (int k = 0; k < n; ++k)
            p.push_back(c + Vec2{std::cos(2 * std::numbers::pi * k / n),
                                 std::sin(2 * std::numbers::pi * k / n)} *
                                r);
        const auto img = rasterize({p}, FillRule::NonZero, w, h);
        const Diff d =
            compare(img, testing::supersampled_coverage({p}, FillRule::NonZero, w, h), w);
        EXPECT_LE(d.max, 1.0f / 255)
            << "circle " << i << " r " << r << " at (" << d.x << ", " << d.y << ")";
    }
}

TEST(Rasterizer, PixelAlignedRectanglesAreExact) {
    const auto img = rasterize({{{2, 3}, {9, 3}, {9, 7}, {2, 7}}}, FillRule::NonZero, 12, 10);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 12; ++x)
            EXPECT_EQ(img.at(x, y), (x >= 2 && x < 9 && y >= 3 && y < 7) ? 1.0f : 0.0f)
                << x << "," << y;
}

TEST(Rasterizer, SharedEdgeIsCoveredExactlyOnce) {
    // Two triangles sharing a diagonal, wound in opposite senses along it.
    const Polygon a{{1, 1}, {15, 1}, {15, 12}}, b{{1, 1}, {15, 12}, {1, 12}};
    const auto ia = rasterize({a}, FillRule::NonZero, 16, 14),
               ib = rasterize({b}, FillRule::NonZero, 16, 14);
    for (int y = 1; y < 12; ++y)
        for (int x = 1; x < 15; ++x)
            EXPECT_NEAR(ia.at(x, y) + ib.at(x, y), 1.0f, 1e-5f) << x << "," << y;
}

TEST(Rasterizer, OverlapsFollowTheFillRule) {
    const std::vector<Polygon> two = {{{2, 2}, {12, 2}, {12, 12}, {2, 12}},
                                      {{6, 6}, {16, 6}, {16, 16}, {6, 16}}};
    const auto nz = rasterize(two, FillRule::NonZero, 20, 20),
               eo = rasterize(two, FillRule::EvenOdd, 20, 20);
    EXPECT_EQ(nz.at(8, 8), 1.0f);
    EXPECT_EQ(eo.at(8, 8), 0.0f);
    EXPECT_EQ(eo.at(3, 3), 1.0f);
}

TEST(Rasterizer, ShapesCutByTheCanvasBordersMatchACroppedLargerCanvas) {
    testing::Rng rng(84);
    for (int i = 0; i < 20; ++i) {
        const Polygon p = random_star(rng, {rng.uniform(-10, 50), rng.uniform(-10, 50)}, 30, 7);
        // The same polygon, shifted by (20, 20), on a canvas 40 px larger.
        Polygon q;
        for (Point v : p) q.push_back(v + Vec2{20, 20});
        const auto small = rasterize({p}, FillRule::NonZero, 40, 40);
        const auto big = rasterize({q}, FillRule::NonZero, 80, 80);
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 40; ++x)
                EXPECT_NEAR(small.at(x, y), big.at(x + 20, y + 20), 1e-4f)
                    << i << " at " << x << "," << y;
    }
}

TEST(Rasterizer, AliasedModeSamplesPixelCentres) {
    testing::Rng rng(85);
    for (int i = 0; i < 20; ++i) {
        const std::vector<Polygon> polys = {random_star(rng, rng.point(30), 14, 9)};
        const auto img = rasterize(polys, FillRule::EvenOdd, 30, 30, false);
        const auto ref = testing::supersampled_coverage(polys, FillRule::EvenOdd, 30, 30, 1);
        const Diff d = compare(img, ref, 30);
        EXPECT_EQ(d.max, 0.0f) << i << " at " << d.x << "," << d.y;
    }
}

TEST(PathEdges, HugeCircleMostlyOffCanvasIsCheapAndRight) {
    // Radius 1e7 px, its leftmost point at x = 20: inside the canvas the edge
    // is straight to 1e-4 px (sagitta of 64 px of arc), so each row's coverage
    // is that of the half-plane x >= 20 + y^2 / (2 r) ~ 20.
    const PathDataResult r =
        parse_path_data("M 20 32 A 1e7 1e7 0 1 1 20000020 32 A 1e7 1e7 0 1 1 20 32 Z");
    ASSERT_FALSE(r.error);
    EdgeList edges;
    edges.reset(64, 64);
    const FlattenStats s = add_path_edges(r.path, Affine::identity(), {}, edges);
    EXPECT_LT(s.segments_out, 5000u);
    for (bool aa : {true, false}) {
        testing::CoverageImage img(64, 64);
        Rasterizer().fill(edges, FillRule::NonZero, aa, img);
        for (int y = 0; y < 64; ++y) {
            EXPECT_NEAR(img.at(19, y), 0.0f, 1e-3f) << y << " aa " << aa;
            EXPECT_NEAR(img.at(20, y), 1.0f, 1e-3f) << y << " aa " << aa;
            EXPECT_NEAR(img.at(63, y), 1.0f, 1e-3f) << y << " aa " << aa;
        }
    }
}

TEST(PathEdges, CoordinatesUpTo1e9KeepTheShape) {
    // A triangle with vertices 1e9 px away whose edges cross the canvas.
    const PathDataResult r = parse_path_data("M -1e9 -1e9 L 1e9 1e9 L -1e9 1e9 Z");
    EdgeList edges;
    edges.reset(32, 32);
    add_path_edges(r.path, Affine::identity(), {}, edges);
    testing::CoverageImage img(32, 32);
    Rasterizer().fill(edges, FillRule::NonZero, true, img);
    const auto ref = testing::supersampled_coverage({{{-1e9, -1e9}, {1e9, 1e9}, {-1e9, 1e9}}},
                                                    FillRule::NonZero, 32, 32);
    EXPECT_LE(compare(img, ref, 32).max, 1.0f / 255);
}

// The same triangle scaled to 1e308, where b - a of two coordinates
// overflows: the edges stay finite and the coverage is the 1e9 triangle's
// (the shape is the same half-planes near the canvas).
TEST(PathEdges, CoordinatesNear1e308KeepTheShape) {
    const auto cover = [](const char* d) {
        const PathDataResult r = parse_path_data(d);
        EdgeList edges;
        edges.reset(32, 32);
        add_path_edges(r.path, Affine::identity(), {}, edges);
        for (const Edge& e : edges.edges())
            EXPECT_TRUE(std::isfinite(e.x0) && std::isfinite(e.x1)) << d;
        testing::CoverageImage img(32, 32);
        Rasterizer().fill(edges, FillRule::NonZero, true, img);
        return img;
    };
    const auto near = cover("M -1e9 -1e9 L 1e9 1e9 L -1e9 1e9 Z");
    const auto far = cover("M -1e308 -1e308 L 1e308 1e308 L -1e308 1e308 Z");
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            EXPECT_NEAR(far.at(x, y), near.at(x, y), 1.0f / 255) << x << "," << y;
}

// fuzz_svg_render: an arc from (150, 20) to (1, -1e308) has a radius near
// 5e307; flattening its pieces near the canvas squared coordinates past the
// double range and never finished. Pieces still huge at the culling depth
// are chords now: the edge building ends, with few segments, all finite.
TEST(PathEdges, ArcReaching1e308EndsWithFiniteEdges) {
    const PathDataResult r =
        parse_path_data("M150 20 A130 130 0 0 1 1 -1e308 A130 130 0 0 1 150 20 Z");
    ASSERT_FALSE(r.error) << r.error->message;
    EdgeList edges;
    edges.reset(96, 96);
    const FlattenStats s = add_path_edges(r.path, Affine::scale(0.32), {}, edges);
    EXPECT_LT(s.segments_out, 10000u);
    for (const Edge& e : edges.edges())
        EXPECT_TRUE(std::isfinite(e.x0) && std::isfinite(e.x1) && std::isfinite(e.y0)) << e.x0;
}

TEST(PathEdges, CurvesLeftOfTheCanvasKeepTheirWinding) {
    // A disc whose left half lies off-canvas: culled curves become chords on x = 0.
    const PathDataResult r =
        parse_path_data("M 0 -20 C 40 -20 40 40 0 40 C -40 40 -40 -20 0 -20 Z");
    EdgeList a, b;
    a.reset(32, 24);
    b.reset(64, 24);
    add_path_edges(r.path, Affine::identity(), {}, a);
    add_path_edges(r.path, Affine::translate({32, 0}), {}, b);
    testing::CoverageImage ia(32, 24), ib(64, 24);
    Rasterizer().fill(a, FillRule::NonZero, true, ia);
    Rasterizer().fill(b, FillRule::NonZero, true, ib);
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x)
            EXPECT_NEAR(ia.at(x, y), ib.at(x + 32, y), 1e-4f) << x << "," << y;
}

} // namespace
} // namespace casteljau
