// Stroke outlines against analytic shapes: the offset distance on random
// curves, caps and joins, dashes along the arc length, zero-length subpaths,
// and hairline coverage through the renderer.
#include "casteljau/curve/path_data.h"
#include "casteljau/flatten/error.h"
#include "casteljau/raster/rasterizer.h"
#include "casteljau/render/renderer.h"
#include "casteljau/stroke/stroker.h"
#include "casteljau/svg/reader.h"
#include "check.h"
#include "corpus.h"
#include "coverage.h"
#include "stroke_cases.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace casteljau {
namespace {

constexpr double kPi = std::numbers::pi;
using testing::area;
using testing::cover;
using testing::parse;
using testing::style;

Rect bounds_of(const std::vector<Polygon>& polys) {
    Rect r = Rect::empty();
    for (const Polygon& p : polys)
        for (Point q : p) r = r.united(q);
    return r;
}

// Distance from q to the cubic (dense sampling, then golden-section refinement).
double distance_to_curve(const CubicBez& c, Point q) {
    int best = 0;
    double bd = 1e300;
    for (int i = 0; i <= 400; ++i) {
        const double d = distance(c.eval(i / 400.0), q);
        if (d < bd) bd = d, best = i;
    }
    double lo = std::max(0, best - 1) / 400.0, hi = std::min(400, best + 1) / 400.0;
    for (int it = 0; it < 60; ++it) {
        const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
        (distance(c.eval(a), q) < distance(c.eval(b), q) ? hi : lo) =
            (distance(c.eval(a), q) < distance(c.eval(b), q) ? b : a);
    }
    return std::min(bd, distance(c.eval(0.5 * (lo + hi)), q));
}

// Strokes cubic `c` w wide at tolerance `tol` and checks that every outline
// vertex, and the midpoint of every outline edge, away from the caps lies
// w/2 +- tol from the curve. Returns how many points it checked.
int check_offsets(const CubicBez& c, double w, double tol, int i) {
    Path p;
    p.move_to(c.start());
    p.cubic_to(c.p[1], c.p[2], c.p[3]);
    std::vector<Polygon> out;
    stroke_outline(p, style(w), tol, out);
    EXPECT_EQ(out.size(), 1u) << "curve " << i;
    if (out.size() != 1) return 0;
    const Polygon& poly = out[0];
    int checked = 0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        for (const Point q : {poly[k], midpoint(poly[k], poly[(k + 1) % poly.size()])}) {
            if (distance(q, c.start()) < w || distance(q, c.end()) < w) continue; // near the caps
            EXPECT_NEAR(distance_to_curve(c, q), w / 2, tol + 1e-9)
                << "curve " << i << " width " << w << " tol " << tol << " at (" << q.x << ", "
                << q.y << ")";
            ++checked;
        }
    }
    return checked;
}

TEST(Stroker, OutlineLiesAtHalfWidthFromRandomCurves) {
    // Away from the caps, every outline vertex and every outline edge midpoint
    // is at width/2 +- tolerance from the curve. Curves whose radius of
    // curvature drops below the width fold their inner offset and are
    // skipped (the fold lies inside the stroke, hidden by the nonzero fill).
    testing::Rng rng(101);
    int checked = 0;
    for (int i = 0; i < 300; ++i) {
        const CubicBez c = testing::random_cubic(rng, 300);
        const double w = rng.log_uniform(0.5, 30), tol = rng.log_uniform(0.02, 0.5);
        double min_radius = 1e300;
        for (int k = 0; k <= 20000; ++k) {
            const double t = k / 20000.0;
            const Vec2 d1 = c.deriv(t), d2 = c.deriv2(t);
            min_radius = std::min(min_radius, std::pow(d1.length(), 3) /
                                                  std::max(1e-300, std::fabs(d1.cross(d2))));
        }
        // Also skipped: curves whose distant parts pass within 2w of each other
        // (loops), where an offset point is nearer the other branch.
        bool approaches = false;
        for (int a = 0; a <= 200 && !approaches; ++a)
            for (int b = a + 20; b <= 200 && !approaches; ++b)
                approaches = distance(c.eval(a / 200.0), c.eval(b / 200.0)) < 2 * w;
        if (min_radius < w || approaches) continue;
        checked += check_offsets(c, w, tol, i);
    }
    EXPECT_GT(checked, 5000);
}

// Distance from q to the closed polyline (a polygon: closed back to its start).
double distance_to_polygon(const Polygon& poly, Point q) {
    double best = 1e300;
    for (std::size_t i = 0; i < poly.size(); ++i)
        best = std::min(best, distance_to_segment(q, poly[i], poly[(i + 1) % poly.size()]));
    return best;
}

// Issue 21, point 3: handles 1e-4 px long along +x on a curve that is a line
// at 45 degrees (to within 1e-4 px) were drawn as a parallelogram 0.7x as
// wide as the stroke, with caps square to +x. Cairo, Skia and resvg draw the
// band: a rectangle of half-width 10 around (30,150)-(150.0001,30).
TEST(Stroker, NearDegenerateHandlesKeepTheFullWidth) {
    const double tol = 0.25, h = 10;
    const Point a{30, 150}, b{150.0001, 30};
    std::vector<Polygon> out;
    stroke_outline(parse("M 30 150 C 30.0001 150 150 30 150.0001 30"), style(2 * h), tol, out);
    ASSERT_EQ(out.size(), 1u);
    const Vec2 u = (b - a).normalized(), n = u.perp();
    const double len = distance(a, b);
    // Every vertex lies on the rectangle's boundary, within the tolerance.
    for (const Point q : out[0]) {
        const double s = (q - a).dot(u), r = std::fabs((q - a).dot(n));
        const double off = s >= 0 && s <= len && r <= h
                               ? std::min({s, len - s, h - r})
                               : std::hypot(std::max({0.0, -s, s - len}), std::max(0.0, r - h));
        EXPECT_LE(off, tol) << "vertex (" << q.x << ", " << q.y << ") is " << off
                            << " px off the rectangle (along " << s << ", across " << r << ")";
    }
    // Its four corners are vertices: the caps are square to the band.
    for (const Point corner : {a + n * h, a - n * h, b + n * h, b - n * h}) {
        double nearest = 1e300;
        for (const Point q : out[0]) nearest = std::min(nearest, distance(q, corner));
        EXPECT_LE(nearest, tol) << "corner (" << corner.x << ", " << corner.y << ")";
    }
    // And it covers the rectangle: the area is 2 h len, to tol per unit of perimeter.
    EXPECT_NEAR(std::fabs(area(out[0])), 2 * h * len, tol * 2 * (len + 2 * h));
}

// Property: strokes (butt caps) of random cubics with one or both handles
// within 1e-3 px of their end points agree with a dense reference outline
// built by the rule of stroker.h: a control point within tol/64 of an end
// point is that end point (tol is at least 0.1 here, so every such handle
// collapses), and the offsets are sampled 6000 times. The Hausdorff distance
// between the two outlines is at most tol plus 0.015 px, the reference's own
// chord error (its chords are at most about 0.3 px long on offsets whose
// radius of curvature is at least h >= 1 px: 0.3^2 / 8 = 0.011, and far
// less on most). Curves whose reference folds (radius of curvature below the
// width) or comes back near itself are skipped.
TEST(Stroker, NearDegenerateHandlesMatchADenseReference) {
    testing::Rng rng(2121);
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
        const double tol = rng.log_uniform(0.1, 0.5), w = rng.log_uniform(2, 10), h = w / 2;
        const int which = rng.integer(0, 2); // 0: start handle short, 1: end, 2: both
        CubicBez c = testing::random_cubic(rng, 400);
        const auto short_handle = [&](Point end) {
            const double len = rng.log_uniform(1e-7, 1e-3), angle = rng.uniform(0, 2 * kPi);
            return end + Vec2{std::cos(angle), std::sin(angle)} * len;
        };
        if (which != 1) c.p[1] = short_handle(c.p[0]);
        if (which != 0) c.p[2] = short_handle(c.p[3]);
        CubicBez ref = c; // the rule: the short handles coincide with their ends
        if (distance(ref.p[1], ref.p[0]) < tol / 64) ref.p[1] = ref.p[0];
        if (distance(ref.p[2], ref.p[3]) < tol / 64) ref.p[2] = ref.p[3];
        // Radius of curvature away from the ends: a collapsed handle leaves the
        // curve like y = x^1.5 there, whose curvature is unbounded but turns
        // the tangent by little.
        double min_radius = 1e300;
        for (int k = 1000; k <= 19000; ++k) {
            const Vec2 d1 = ref.deriv(k / 20000.0), d2 = ref.deriv2(k / 20000.0);
            min_radius = std::min(min_radius, std::pow(d1.length(), 3) /
                                                  std::max(1e-300, std::fabs(d1.cross(d2))));
        }
        // Comes back: two points more than 4w apart along the curve (measured
        // on 400 chords) lie within 2w of each other.
        std::vector<double> along(401, 0.0);
        for (int k = 1; k <= 400; ++k)
            along[std::size_t(k)] = along[std::size_t(k - 1)] +
                                    distance(ref.eval((k - 1) / 400.0), ref.eval(k / 400.0));
        bool approaches = false;
        for (int a = 0; a <= 400 && !approaches; ++a)
            for (int b = a + 1; b <= 400 && !approaches; ++b)
                approaches = along[std::size_t(b)] - along[std::size_t(a)] > 4 * w &&
                             distance(ref.eval(a / 400.0), ref.eval(b / 400.0)) < 2 * w;
        if (min_radius < w || approaches) continue;
        // The reference: left offsets forward, right offsets back, closed by the caps.
        const int n = 6000;
        Polygon dense(2 * (n + 1));
        for (int k = 0; k <= n; ++k) {
            const double t = double(k) / n;
            Vec2 d = ref.deriv(t);
            if (d.length_sq() == 0) d = t == 0 ? ref.p[2] - ref.p[0] : ref.p[3] - ref.p[1];
            const Vec2 nk = d.normalized().perp() * h;
            dense[std::size_t(k)] = ref.eval(t) + nk;
            dense[std::size_t(2 * n + 1 - k)] = ref.eval(t) - nk;
        }
        Path p;
        p.move_to(c.start());
        p.cubic_to(c.p[1], c.p[2], c.p[3]);
        std::vector<Polygon> out;
        stroke_outline(p, style(w), tol, out);
        ASSERT_EQ(out.size(), 1u) << "curve " << i;
        const Polygon& poly = out[0];
        const double bound = tol + 0.015;
        double worst = 0;
        for (std::size_t k = 0; k < poly.size(); ++k)
            for (const Point q : {poly[k], midpoint(poly[k], poly[(k + 1) % poly.size()])})
                worst = std::max(worst, distance_to_polygon(dense, q));
        for (const Point q : dense) worst = std::max(worst, distance_to_polygon(poly, q));
        EXPECT_LE(worst, bound) << "curve " << i << " (short handles: "
                                << (which == 0   ? "start"
                                    : which == 1 ? "end"
                                                 : "both")
                                << ") width " << w << " tol " << tol << ": C " << c.p[0].x << " "
                                << c.p[0].y << ", " << c.p[1].x << " " << c.p[1].y << ", "
                                << c.p[2].x << " " << c.p[2].y << ", " << c.p[3].x << " "
                                << c.p[3].y;
        ++checked;
    }
    EXPECT_GT(checked, 100);
}

// (b) holds between samples, not only at them: handles 0.01 to 0.05 px long
// (above tol/64, so kept) both along one direction u at 30 to 90 degrees to
// the chord. The normal is perpendicular to u at both ends and to the chord
// in between, and the curve is within 0.05 px of its chord, so the flattener
// asks for no vertex inside: testing the normal at the ends alone drew a
// parallelogram, whose sides lie h |sin| of that angle from the curve.
// Away from the caps the outline is at h +- tol from the curve.
TEST(Stroker, NormalTurnIsBoundedBetweenSamples) {
    testing::Rng rng(2122);
    int checked = 0;
    for (int i = 0; i < 100; ++i) {
        const double tol = rng.log_uniform(0.1, 0.5), w = rng.log_uniform(1, 30);
        const Point a = rng.point(300), b = rng.point(300);
        if (distance(a, b) < 4 * w) continue;
        const double chord = std::atan2((b - a).y, (b - a).x);
        const double angle = chord + rng.uniform(kPi / 6, kPi / 2) * (rng.integer(0, 1) ? 1 : -1);
        const Vec2 u{std::cos(angle), std::sin(angle)};
        const CubicBez c{{a, a + u * rng.uniform(0.01, 0.05), b - u * rng.uniform(0.01, 0.05), b}};
        checked += check_offsets(c, w, tol, i);
    }
    EXPECT_GT(checked, 100);
}

TEST(Stroker, CapsExtendAsSpecified) {
    const Path line = parse("M10 10 L90 10");
    const double w = 8;
    std::vector<Polygon> butt, square, round;
    stroke_outline(line, style(w, LineCap::Butt), 0.01, butt);
    stroke_outline(line, style(w, LineCap::Square), 0.01, square);
    stroke_outline(line, style(w, LineCap::Round), 0.01, round);
    EXPECT_NEAR(bounds_of(butt).x0, 10, 1e-12);
    EXPECT_NEAR(bounds_of(square).x0, 10 - w / 2, 1e-12); // a square cap adds exactly w/2
    EXPECT_NEAR(bounds_of(square).x1, 90 + w / 2, 1e-12);
    EXPECT_NEAR(bounds_of(round).x1, 90 + w / 2, 0.01);
    EXPECT_NEAR(std::fabs(area(butt[0])), 80 * w, 1e-9);
    EXPECT_NEAR(std::fabs(area(square[0])), (80 + w) * w, 1e-9);
    EXPECT_NEAR(std::fabs(area(round[0])), 80 * w + std::numbers::pi * w * w / 4, 0.2);
}

TEST(Stroker, MiterBeyondTheLimitBecomesABevel) {
    // A V whose arms meet at 30 degrees: miter ratio 1 / sin(15 deg) = 3.864.
    const double dx = 100 * std::tan(15 * std::numbers::pi / 180);
    Path v;
    v.move_to({50 - dx, 100});
    v.line_to({50, 0});
    v.line_to({50 + dx, 100});
    std::vector<Polygon> miter, clipped, bevel;
    StrokeGeometry s = style(10);
    s.miter_limit = 3.9; // 3.864 <= 3.9: mitered
    stroke_outline(v, s, 0.01, miter);
    s.miter_limit = 3.8; // beyond: bevel
    stroke_outline(v, s, 0.01, clipped);
    stroke_outline(v, style(10, LineCap::Butt, LineJoin::Bevel), 0.01, bevel);
    // The miter tip lies h / sin(15 deg) above the vertex.
    EXPECT_NEAR(bounds_of(miter).y0, -5 / std::sin(15 * std::numbers::pi / 180), 1e-9);
    EXPECT_NEAR(bounds_of(clipped).y0, bounds_of(bevel).y0, 1e-12);
    EXPECT_GT(bounds_of(clipped).y0, bounds_of(miter).y0 + 10);
}

TEST(Stroker, DashesFollowThePatternAlongTheArcLength) {
    // A quarter circle of radius 100 (arc length 50 pi = 157.08), dashes 10 on
    // 5 off: the covered length is the pattern's duty over the arc.
    const Path arc = parse("M100 0 A100 100 0 0 1 0 100");
    StrokeGeometry s = style(2);
    s.dashes = {10, 5};
    std::vector<Polygon> out;
    stroke_outline(arc, s, 0.001, out);
    const double length = 50 * std::numbers::pi;
    const double full = std::floor(length / 15), rest = std::min(10.0, length - 15 * full);
    double covered = 0;
    for (const Polygon& p : out) covered += std::fabs(area(p)) / 2; // width 2: area / width
    EXPECT_NEAR(covered, full * 10 + rest, 0.01);
    EXPECT_EQ(out.size(), std::size_t(full + (rest > 0 ? 1 : 0)));
    // A negative offset: -5 wraps to 10, so the path starts with the 5-long
    // gap and the first dash covers arc length [5, 15], starting at angle 5/100.
    s.dash_offset = -5;
    out.clear();
    stroke_outline(arc, s, 0.001, out);
    EXPECT_NEAR(std::fabs(area(out[0])) / 2, 10.0, 0.01);
    const Point start = midpoint(out[0].front(), out[0].back()); // the butt cap's middle
    EXPECT_NEAR(start.x, 100 * std::cos(0.05), 0.01);
    EXPECT_NEAR(start.y, 100 * std::sin(0.05), 0.01);
    // An odd count repeats: {10} is {10, 10}.
    s.dashes = {10};
    s.dash_offset = 0;
    out.clear();
    stroke_outline(arc, s, 0.001, out);
    EXPECT_EQ(out.size(), std::size_t(std::ceil(length / 20)));
    // All zero: solid.
    s.dashes = {0, 0};
    out.clear();
    stroke_outline(arc, s, 0.001, out);
    EXPECT_EQ(out.size(), 1u);
}

// fuzz_svg_render found a dashed cubic 12.9M px long, of which a 96 px
// image shows a little, taking over 2 s: every dash was built. Now dashes out
// of reach of the visible box are not built (and the ones crossing its reach
// are trimmed there): the image is the same, from a handful of dashes.
TEST(Stroker, DashesOutOfReachOfTheVisibleBoxAreNotBuilt) {
    StrokeGeometry s = style(10, LineCap::Round);
    s.dashes = {20, 8, 4, 8};
    const Rect visible{0, 0, 96, 96};
    for (const char* d : {"M-50000 40 L50000 60", "M-3e4 -3e4 C 9e4 40 -9e4 60 3e4 3e4",
                          "M50 20 C 190 1288888 250 26 -290 -160"}) {
        const Path path = parse(d);
        std::vector<Polygon> all, seen;
        stroke_outline(path, s, 0.25, all);
        stroke_outline(path, s, 0.25, seen, visible);
        const testing::CoverageImage full = cover(all, 96, 96), part = cover(seen, 96, 96);
        float covered = 0;
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 96; ++x) {
                covered += full.at(x, y);
                ASSERT_NEAR(part.at(x, y), full.at(x, y), 1e-4f) << d << " at " << x << "," << y;
            }
        EXPECT_GT(covered, 100.0f) << d; // the stroke does cross the image
        EXPECT_LT(seen.size(), 40u) << d << ": " << all.size() << " dashes in all";
    }
}

// fuzz_svg_render (regressions/svg_render/dashes-on-a-chord-7e17-long.svg):
// a cubic with a control point at 8e20 flattens, for dashing, into a last
// chord 7.4e17 long that ends in the visible box, where positions along it
// are multiples of 128; adding a 4-unit dash to one did not move the walk,
// which emitted 2^19 dots at one point (8.4M points, 800 MB for a 96 px
// image). The visible part, 220 units of chords, holds a dozen dashes.
TEST(Stroker, DashesOnAChordFarLongerThanTheBoxFollowTheBox) {
    StrokeGeometry s = style(10, LineCap::Round);
    s.dashes = {20, 8, 4, 8};
    const double scale = 0.3; // the fuzz target's: 320 x 240 drawn at 96 x 72
    const Rect strip{-1 / scale, -1 / scale, 97 / scale, 65 / scale};
    std::vector<Polygon> out;
    stroke_outline(parse("M150 200 C 1 -5310 8e20 260 290 160"), s, 0.25 / scale, out, strip);
    std::size_t points = 0;
    for (const Polygon& p : out) {
        points += p.size();
        for (Point q : p) EXPECT_TRUE(q.is_finite());
    }
    EXPECT_GT(out.size(), 0u); // the dashes near both ends are in the box
    EXPECT_LT(out.size(), 40u) << points << " points";
}

// Past kMaxDashes (2^20) dash boundaries the path is stroked solid, as
// Skia strokes a pattern of more than a million dashes (the review's "0
// 1e-6" on a line 120 long: a million dots, 700 MB, and the rest undrawn).
// A pattern within the limit is dashed.
TEST(Stroker, APatternOfMoreThanAMillionDashesIsStrokedSolid) {
    StrokeGeometry s = style(10, LineCap::Round);
    s.dashes = {0, 1e-6};
    std::vector<Polygon> fine, plain;
    stroke_outline(parse("M0 0 H120"), s, 0.01, fine);
    stroke_outline(parse("M0 0 H120"), style(10, LineCap::Round), 0.01, plain);
    ASSERT_EQ(fine.size(), 1u);
    EXPECT_EQ(fine, plain);
    s.dashes = {0, 1e-2}; // 12,000 dots
    fine.clear();
    stroke_outline(parse("M0 0 H120"), s, 0.01, fine);
    EXPECT_GE(fine.size(), 12000u) << "a dot every 0.01, as the sum of gaps rounds";
    EXPECT_LE(fine.size(), 12001u);
}

// Solid strokes of geometry reaching 1e308 (found by fuzz_svg_render: the
// stroke of an arc of radius 5e307 sampled the whole arc): only the part near
// the visible box is built, and a nearly horizontal line from -1e300 to 1e300
// gives the same outline there as one from -1e9 to 1e9.
TEST(Stroker, SolidStrokesBuildOnlyTheVisiblePart) {
    const Rect visible{0, 0, 300, 300};
    std::vector<Polygon> arc;
    stroke_outline(parse("M150 20 A130 130 0 0 1 1 -1e308 A130 130 0 0 1 150 20 Z"),
                   style(3, LineCap::Round), 0.25, arc, visible);
    std::size_t points = 0;
    for (const Polygon& p : arc) {
        points += p.size();
        for (Point q : p) EXPECT_TRUE(q.is_finite());
    }
    EXPECT_LT(points, 10000u);
    const auto band = [&](const char* d) { // where the outline crosses x = 150
        std::vector<Polygon> out;
        stroke_outline(parse(d), style(5), 0.25, out, visible);
        Rect b = Rect::empty();
        for (const Polygon& p : out)
            for (std::size_t i = 0; i < p.size(); ++i) {
                const Point u = p[i], v = p[(i + 1) % p.size()];
                if ((u.x < 150) != (v.x < 150)) b = b.united(lerp(u, v, (150 - u.x) / (v.x - u.x)));
            }
        return b;
    };
    const Rect near = band("M-1e9 100 L1e9 200"), far = band("M-1e300 100 L1e300 200");
    EXPECT_NEAR(far.y0, near.y0, 1e-5); // the 1e9 line is 7.5e-6 px higher at x = 150
    EXPECT_NEAR(far.y1, near.y1, 1e-5);
    EXPECT_NEAR(far.y0, 147.5, 1e-6);
}

// fuzz_svg_render: stroke-width 1e22 made the normal-turn step 0 (1 - tol/2h
// rounds to 1), and a round cap infinitely many points (int(inf), undefined).
TEST(Stroker, AStroke1e22WideHasBoundedRoundCapsAndJoins) {
    std::vector<Polygon> out;
    stroke_outline(parse("M150 200 C 190 120 250 260 290 160 L 300 300"),
                   style(1e22, LineCap::Round, LineJoin::Round), 0.25, out, Rect{0, 0, 320, 240});
    std::size_t points = 0;
    for (const Polygon& p : out) {
        points += p.size();
        for (Point q : p) EXPECT_TRUE(q.is_finite());
    }
    EXPECT_GT(points, 0u);
    EXPECT_LT(points, 1u << 20);
}

// 8000 round joins on a stroke 1e6 px wide, one subpath: 4400 points a join
// took 1.2 GB on the way to coverage, past the 1 GiB promised for hostile
// input, as the outline's point limit (2^23, stroker.cpp) was only checked
// between subpaths. A subpath that outgrows it is dropped, and so is what
// follows it (a small square); 1000 such joins are within it, and drawn.
// A stroke 1e199 wide along a line 1e200 long: lengths whose squares
// overflow. Built scaled down and back, it is the rectangle it should be
// (before, every normal was NaN and the outline took gigabytes).
TEST(Stroker, AStrokeBeyondTheSquaresOfDoublesIsBuiltScaled) {
    Path p;
    p.move_to({0, 0});
    p.line_to({1e200, 0});
    StrokeGeometry g;
    g.width = 1e199;
    Stroker stroker;
    const auto polys = stroker.outline(p, g, 0.25, Rect{-1e201, -1e201, 1e201, 1e201});
    ASSERT_EQ(polys.size(), 1u);
    Rect b = Rect::empty();
    for (const Point& q : polys[0]) {
        ASSERT_TRUE(std::isfinite(q.x) && std::isfinite(q.y)) << q.x << " " << q.y;
        b = b.united(Rect{q.x, q.y, q.x, q.y});
    }
    EXPECT_LE(polys[0].size(), 8u);
    EXPECT_NEAR(b.x0, 0, 1e186);
    EXPECT_NEAR(b.x1, 1e200, 1e186);
    EXPECT_NEAR(b.y0, -5e198, 1e186);
    EXPECT_NEAR(b.y1, 5e198, 1e186);
}

TEST(Stroker, ASubpathBeyondThePointLimitIsNotDrawn) {
    const auto zigzag_then_square = [](int joins) {
        std::string d = "M30 30";
        for (int i = 0; i <= joins; ++i) d += i % 2 ? " L30 30" : " L34 30";
        return parse((d + " M10 10 h4 v4 h-4 z").c_str());
    };
    const StrokeGeometry wide = style(1e6, LineCap::Round, LineJoin::Round);
    std::vector<Polygon> out;
    stroke_outline(zigzag_then_square(8000), wide, 0.25, out, Rect{0, 0, 64, 64});
    EXPECT_TRUE(out.empty()) << out.size() << " polygons";
    out.clear();
    stroke_outline(zigzag_then_square(1000), wide, 0.25, out, Rect{0, 0, 64, 64});
    EXPECT_EQ(out.size(), 3u); // the zigzag's outline, the closed square's two sides
}

TEST(Stroker, ZeroLengthSubpaths) {
    const Path dot = parse("M50 50 L50 50");
    std::vector<Polygon> round, square, butt;
    stroke_outline(dot, style(10, LineCap::Round), 0.01, round);
    stroke_outline(dot, style(10, LineCap::Square), 0.01, square);
    stroke_outline(dot, style(10, LineCap::Butt), 0.01, butt);
    ASSERT_EQ(round.size(), 1u);
    EXPECT_NEAR(std::fabs(area(round[0])), std::numbers::pi * 25, 0.2);
    EXPECT_NEAR(std::fabs(area(square[0])), 100, 1e-12);
    EXPECT_TRUE(butt.empty());
}

// Zero-length dashes are dots (SVG 2: each draws its caps), at a subpath's
// start and end as well as between: resvg's stroke-dasharray 0-n tests.
// Before, the dot at the start was skipped and the one at the end never
// reached (a line 120 long dashed "0 40" had 2 dots of 4).
TEST(Stroker, ZeroLengthDashesAreDotsAtBothEnds) {
    StrokeGeometry s = style(10, LineCap::Round);
    s.dashes = {0, 40};
    const auto centres = [&](const char* d) {
        std::vector<Polygon> out;
        stroke_outline(parse(d), s, 0.01, out);
        std::set<std::pair<long, long>> at;
        for (const Polygon& p : out) {
            const Rect b = bounds_of({p});
            EXPECT_NEAR(b.width(), 10, 0.01);
            at.insert({std::lround((b.x0 + b.x1) / 2), std::lround((b.y0 + b.y1) / 2)});
        }
        return at;
    };
    EXPECT_EQ(centres("M0 0 H120"),
              (std::set<std::pair<long, long>>{{0, 0}, {40, 0}, {80, 0}, {120, 0}}));
    // A closed square of side 80: dots every 40 round it, its start too.
    EXPECT_EQ(centres("M0 0 H80 V80 H0 Z").size(), 8u);
    // A dash that ends where the path ends is no dot: 10 on, 5 off over 25.
    s.dashes = {10, 5};
    std::vector<Polygon> out;
    stroke_outline(parse("M0 0 H25"), s, 0.01, out);
    EXPECT_EQ(out.size(), 2u);
    // Nor is one that ends where the path starts (an offset of a whole dash).
    s.dash_offset = 10;
    out.clear();
    stroke_outline(parse("M0 0 H25"), s, 0.01, out);
    EXPECT_EQ(out.size(), 2u) << "a gap, then dashes at 5 and 20";
}

// A zero-length dash's square faces the path's way there (SVG 2: the
// direction of the path at the dash; rsvg-convert turns it so too); a
// subpath of no length faces +x. Before, every square was axis-aligned.
TEST(Stroker, ASquareDotFacesThePath) {
    StrokeGeometry s = style(10, LineCap::Square);
    s.dashes = {0, 50};
    std::vector<Polygon> diagonal;
    stroke_outline(parse("M0 0 L100 100"), s, 0.01, diagonal);
    ASSERT_EQ(diagonal.size(), 3u); // at 0, 50 and 100 along the 141 of the line
    for (const Polygon& p : diagonal) {
        EXPECT_NEAR(bounds_of({p}).width(), 10 * std::numbers::sqrt2, 1e-9);
        EXPECT_NEAR(std::fabs(area(p)), 100, 1e-9);
    }
    std::vector<Polygon> lone;
    stroke_outline(parse("M0 0 L0 0"), style(10, LineCap::Square), 0.01, lone);
    ASSERT_EQ(lone.size(), 1u);
    EXPECT_NEAR(bounds_of(lone).width(), 10, 1e-12);
}

// A dot turns as a stroke's outline turns, so that where one overlaps a
// stroke the nonzero windings add up (the reviewer's "M20 20 H60 M60 20
// L60 20": the dot cut a crescent out of the round cap, and a dash "40 0 0
// 100" the same at the dash's end; square caps lost their square).
TEST(Stroker, ADotOverAStrokeAddsToIt) {
    for (const LineCap cap : {LineCap::Round, LineCap::Square}) {
        std::vector<Polygon> line, dot;
        stroke_outline(parse("M20 20 H60"), style(20, cap), 0.01, line);
        stroke_outline(parse("M60 20 L60 20"), style(20, cap), 0.01, dot);
        ASSERT_EQ(line.size(), 1u);
        ASSERT_EQ(dot.size(), 1u);
        EXPECT_GT(area(line[0]) * area(dot[0]), 0) << "the same turn";
        std::vector<Polygon> both;
        stroke_outline(parse("M20 20 H60 M60 20 L60 20"), style(20, cap), 0.01, both);
        const testing::CoverageImage c = cover(both, 80, 40);
        for (const int x : {55, 62, 66})
            EXPECT_NEAR(c.at(x, 20), 1.0f, 1e-6f) << x << " " << int(cap);
        StrokeGeometry dashed = style(20, cap);
        dashed.dashes = {40, 0, 0, 100};
        std::vector<Polygon> dash;
        stroke_outline(parse("M20 20 H60"), dashed, 0.01, dash);
        const testing::CoverageImage d = cover(dash, 80, 40);
        for (const int x : {55, 62, 66})
            EXPECT_NEAR(d.at(x, 20), 1.0f, 1e-6f) << x << " " << int(cap);
    }
}

TEST(Stroker, DegenerateAndCoincidentSegments) {
    // A zero-length segment in the middle changes nothing.
    std::vector<Polygon> plain, with_dot;
    stroke_outline(parse("M10 10 L90 10"), style(6), 0.01, plain);
    stroke_outline(parse("M10 10 L50 10 L50 10 L90 10"), style(6), 0.01, with_dot);
    EXPECT_EQ(bounds_of(plain), bounds_of(with_dot));
    // Turning straight back (a 180-degree join): a round join makes the far
    // end a half disc; a miter would be infinite and falls back to a bevel.
    std::vector<Polygon> back_round, back_miter;
    stroke_outline(parse("M10 10 L50 10 L20 10"), style(6, LineCap::Butt, LineJoin::Round), 0.01,
                   back_round);
    stroke_outline(parse("M10 10 L50 10 L20 10"), style(6, LineCap::Butt, LineJoin::Miter), 0.01,
                   back_miter);
    EXPECT_NEAR(bounds_of(back_round).x1, 53, 0.01);
    EXPECT_NEAR(bounds_of(back_miter).x1, 50, 1e-9);
    EXPECT_NEAR(bounds_of(back_round).y0, 7, 1e-9);
    // A cusp inside a cubic (control points crossing): the outline stays
    // finite and within width/2 of the curve's hull.
    std::vector<Polygon> cusp;
    stroke_outline(parse("M0 0 C 100 100 0 100 100 0"), style(4), 0.05, cusp);
    const Rect b = bounds_of(cusp);
    EXPECT_TRUE(std::isfinite(b.x0) && std::isfinite(b.y1));
    EXPECT_GE(b.x0, -2 - 1e-9);
    EXPECT_LE(b.y1, 75 + 2 + 1e-9);
}

} // namespace
} // namespace casteljau
