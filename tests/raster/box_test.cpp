// Axis-aligned rectangles (raster/box.h) against the general accumulation
// and sweep, and against the exact product of overlaps.
#include "casteljau/raster/box.h"
#include "casteljau/raster/rasterizer.h"
#include "corpus.h"
#include "coverage.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

namespace casteljau {
namespace {

struct Box {
    double x0, y0, x1, y1;
};

// The rectangle's outline for the rows [row_begin, row_end) of a w x h
// canvas. Split: its left side in two collinear edges, the same outline
// that fill_box declines, so the accumulation and the sweep draw it.
EdgeList box_edges(const Box& b, int w, int h, int row_begin, int row_end, bool split) {
    EdgeList edges;
    edges.reset({0, 0, w, h}, row_begin, row_end);
    const Point p[] = {{b.x0, b.y0}, {b.x1, b.y0}, {b.x1, b.y1}, {b.x0, b.y1}};
    for (int i = 0; i < 3; ++i) edges.add_line(p[i], p[i + 1]);
    if (split) {
        const Point mid{b.x0, 0.5 * (b.y0 + b.y1)};
        edges.add_line(p[3], mid);
        edges.add_line(mid, p[0]);
    } else {
        edges.add_line(p[3], p[0]);
    }
    return edges;
}

testing::CoverageImage draw(const EdgeList& edges, int w, int h) {
    testing::CoverageImage img(w, h);
    Rasterizer r;
    r.fill(edges, FillRule::NonZero, true, img);
    EXPECT_TRUE(img.order_ok());
    return img;
}

// Mostly fractional coordinates, some on pixel borders, some past the canvas.
double coordinate(testing::Rng& rng, double extent) {
    const double v = rng.uniform(-0.3 * extent, 1.3 * extent);
    return rng.integer(0, 3) == 0 ? std::round(v) : v;
}

double overlap(double a0, double a1, double i) {
    return std::max(0.0, std::min(a1, i + 1) - std::max(a0, i));
}

TEST(Box, DeclinesAllButTwoVerticalEdgesOverTheSameRows) {
    struct Null final : SpanSink {
        void span(const Span&) override { ADD_FAILURE() << "a span from a declined outline"; }
    } null;
    const Box b{2.5, 3.25, 9.75, 7.5};
    EXPECT_FALSE(fill_box(box_edges(b, 12, 10, 0, 10, true), null));
    EdgeList turned;
    turned.reset(12, 10);
    const Point p[] = {{2, 3}, {9, 3.1}, {9, 7}, {2, 7}};
    for (int i = 0; i < 4; ++i) turned.add_line(p[i], p[(i + 1) % 4]);
    EXPECT_FALSE(fill_box(turned, null));
    EdgeList two; // two vertical edges, but over different rows: not a rectangle
    two.reset(12, 10);
    two.add_line({2, 1}, {2, 8});
    two.add_line({6, 9}, {6, 2});
    EXPECT_FALSE(fill_box(two, null));
}

TEST(Box, CoverageIsTheProductOfOverlaps) {
    testing::Rng rng(251);
    const int w = 40, h = 30;
    for (int i = 0; i < 200; ++i) {
        Box b{coordinate(rng, w), coordinate(rng, h), coordinate(rng, w), coordinate(rng, h)};
        if (b.x0 > b.x1) std::swap(b.x0, b.x1);
        if (rng.integer(0, 1)) std::swap(b.y0, b.y1); // either winding
        const auto img = draw(box_edges(b, w, h, 0, h, false), w, h);
        const double y0 = std::min(b.y0, b.y1), y1 = std::max(b.y0, b.y1);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double want = overlap(b.x0, b.x1, x) * overlap(y0, y1, y);
                ASSERT_NEAR(img.at(x, y), want, 1e-5)
                    << "box " << i << " (" << b.x0 << ", " << b.y0 << ")-(" << b.x1 << ", " << b.y1
                    << ") at " << x << "," << y;
            }
    }
}

TEST(Box, MatchesTheSweepOfTheSameOutline) {
    testing::Rng rng(252);
    const int w = 50, h = 40;
    for (int i = 0; i < 200; ++i) {
        const Box b{coordinate(rng, w), coordinate(rng, h), coordinate(rng, w), coordinate(rng, h)};
        const auto fast = draw(box_edges(b, w, h, 0, h, false), w, h);
        const auto swept = draw(box_edges(b, w, h, 0, h, true), w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                ASSERT_NEAR(fast.at(x, y), swept.at(x, y), 1e-5)
                    << "box " << i << " (" << b.x0 << ", " << b.y0 << ")-(" << b.x1 << ", " << b.y1
                    << ") at " << x << "," << y;
    }
}

TEST(Box, BandsGiveTheWholeFramesBits) {
    testing::Rng rng(253);
    const int w = 30, h = 30;
    for (int i = 0; i < 50; ++i) {
        const Box b{coordinate(rng, w), coordinate(rng, h), coordinate(rng, w), coordinate(rng, h)};
        const auto whole = draw(box_edges(b, w, h, 0, h, false), w, h);
        const int cut = rng.integer(1, h - 1);
        testing::CoverageImage banded(w, h);
        Rasterizer r;
        r.fill(box_edges(b, w, h, 0, cut, false), FillRule::NonZero, true, banded);
        r.fill(box_edges(b, w, h, cut, h, false), FillRule::NonZero, true, banded);
        EXPECT_EQ(whole.data(), banded.data()) << "box " << i << " cut at row " << cut;
    }
}

} // namespace
} // namespace casteljau
