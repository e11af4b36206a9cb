// Gradients: the parameter t at known points against the SVG formulas, each
// spread method, unpremultiplied and linear-light interpolation, and the SVG
// side (units, gradientTransform, href inheritance, bad references).
#include "casteljau/paint/canvas.h"
#include "casteljau/paint/gradient.h"
#include "casteljau/render/renderer.h"
#include "casteljau/svg/color.h"
#include "casteljau/svg/reader.h"
#include "corpus.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <utility>
#include <vector>

namespace casteljau {
namespace {

Gradient two_stops(Gradient::Kind kind, Spread spread, Rgba a = {0, 0, 0, 1},
                   Rgba b = {1, 1, 1, 1}) {
    Gradient g;
    g.kind = kind;
    g.spread = spread;
    g.stops = {{0, a}, {1, b}};
    return g;
}

TEST(Gradient, LinearParameterAndSpreads) {
    // p1 = (10, 0), p2 = (30, 0) in device space: t = (x - 10) / 20.
    for (Spread s : {Spread::Pad, Spread::Reflect, Spread::Repeat}) {
        Gradient g = two_stops(Gradient::Kind::Linear, s);
        g.p1 = {10, 0}, g.p2 = {30, 0};
        GradientShader sh;
        ASSERT_TRUE(sh.prepare(g, Affine::identity(), 1));
        EXPECT_NEAR(sh.parameter({20, 7}), 0.5, 1e-12);
        const double before = sh.parameter({5, 0}),
                     after = sh.parameter({35, 0}); // t = -0.25, 1.25
        const double want_before = s == Spread::Pad ? 0.0 : s == Spread::Reflect ? 0.25 : 0.75;
        const double want_after = s == Spread::Pad ? 1.0 : s == Spread::Reflect ? 0.75 : 0.25;
        EXPECT_NEAR(before, want_before, 1e-12) << int(s);
        EXPECT_NEAR(after, want_after, 1e-12) << int(s);
    }
}

TEST(Gradient, RadialParameterIsTheFractionFromFocalToCircle) {
    testing::Rng rng(91);
    for (int i = 0; i < 200; ++i) {
        Gradient g = two_stops(Gradient::Kind::Radial, Spread::Pad);
        g.center = rng.point(100);
        g.radius = rng.uniform(5, 50);
        const double a = rng.uniform(0, 6.28), rf = rng.uniform(0, 0.9) * g.radius;
        g.focal = g.center + Vec2{std::cos(a), std::sin(a)} * rf;
        GradientShader sh;
        ASSERT_TRUE(sh.prepare(g, Affine::identity(), 1));
        const double b = rng.uniform(0, 6.28), lambda = rng.uniform(0, 1);
        const Point on_circle = g.center + Vec2{std::cos(b), std::sin(b)} * g.radius;
        EXPECT_NEAR(sh.parameter(lerp(g.focal, on_circle, lambda)), lambda, 1e-9) << i;
        EXPECT_NEAR(sh.parameter(g.focal), 0.0, 1e-9) << i;
    }
}

TEST(Gradient, AFocalRadiusStartsTheGradientOnItsCircle) {
    // SVG 2's fr: t is the fraction of the way from the start circle (f, r0)
    // to the end circle (c, r), on the circle between them.
    testing::Rng rng(92);
    for (int i = 0; i < 200; ++i) {
        Gradient g = two_stops(Gradient::Kind::Radial, Spread::Reflect);
        g.center = rng.point(100);
        g.radius = rng.uniform(5, 50);
        g.focal_radius = rng.uniform(0, 0.8) * g.radius;
        const double a = rng.uniform(0, 6.28);
        const double rf = rng.uniform(0, 0.9) * (g.radius - g.focal_radius);
        g.focal = g.center + Vec2{std::cos(a), std::sin(a)} * rf;
        GradientShader sh;
        ASSERT_TRUE(sh.prepare(g, Affine::identity(), 1));
        // Down to the circle of radius 0, at t = -r0 / (r - r0), or to t = -1
        // (reflected: |t|).
        const double lambda =
            rng.uniform(std::max(-1.0, -g.focal_radius / (g.radius - g.focal_radius)), 1);
        const double b = rng.uniform(0, 6.28);
        const Point p = lerp(g.focal, g.center, lambda) +
                        Vec2{std::cos(b), std::sin(b)} *
                            (g.focal_radius + lambda * (g.radius - g.focal_radius));
        EXPECT_NEAR(sh.parameter(p), std::fabs(lambda), 1e-9) << i;
    }
}

// The t of a cone's point by brute force (SVG 2's radial gradient notes, as
// canvas says it): of the circles c(w) = f + w (c - f), r(w) = fr + w (r -
// fr) with r(w) >= 0 that pass through p, the one of the largest w, found
// as the last sign change of |p - c(w)| - r(w) on a fine grid of w; NaN
// where none does.
double cone_reference(const Gradient& g, Point p) {
    double found = NAN, prev = NAN;
    constexpr int kSteps = 200000;
    for (int k = 0; k <= kSteps; ++k) {
        const double w = -20 + 40.0 * k / kSteps,
                     r = g.focal_radius + w * (g.radius - g.focal_radius);
        const Point c = g.focal + (g.center - g.focal) * w;
        const double f = r >= 0 ? (p - c).length() - r : NAN;
        if (!std::isnan(f) && !std::isnan(prev) && (f <= 0) != (prev <= 0)) found = w;
        prev = f;
    }
    return found;
}

// A focal circle outside the end circle (or crossing it) makes a cone
// (SVG 2; browsers, librsvg and resvg draw it): inside, the largest t whose
// circle passes through the point; outside, no paint. SVG 1.1 moved the
// focal point onto the circle, which this renderer did before.
TEST(Gradient, CirclesThatDoNotNestSweepACone) {
    testing::Rng rng(25);
    int inside = 0, outside = 0;
    for (int trial = 0; trial < 40; ++trial) {
        Gradient g = two_stops(Gradient::Kind::Radial, Spread::Pad);
        g.center = {0, 0}, g.radius = rng.uniform(5, 20);
        g.focal_radius = trial % 2 ? rng.uniform(0, 10) : 0;
        const double a = rng.uniform(0, 6.3);
        const double dist = std::fabs(g.radius - g.focal_radius) + rng.uniform(0.5, 30);
        g.focal = Point{0, 0} + Vec2{std::cos(a), std::sin(a)} * dist;
        GradientShader sh;
        ASSERT_TRUE(sh.prepare(g, Affine::identity(), 1));
        for (int k = 0; k < 5; ++k) {
            const Point p = rng.point(100) - Vec2{50, 50};
            const double want = cone_reference(g, p), got = sh.parameter(p);
            if (std::isnan(want)) {
                ++outside;
                EXPECT_TRUE(std::isnan(got)) << trial << ": " << p.x << "," << p.y << " " << got;
            } else {
                ++inside;
                EXPECT_NEAR(got, std::clamp(want, 0.0, 1.0), 1e-3)
                    << trial << ": " << p.x << "," << p.y;
            }
        }
    }
    EXPECT_GT(inside, 20);
    EXPECT_GT(outside, 20);
}

// Outside the cone nothing is painted: a transparent pixel, and an opaque
// gradient is not stored as opaque (store_opaque declines).
TEST(Gradient, OutsideTheConeIsTransparent) {
    Gradient g = two_stops(Gradient::Kind::Radial, Spread::Pad);
    g.center = {50, 50}, g.radius = 10, g.focal = {90, 50};
    GradientShader sh;
    ASSERT_TRUE(sh.prepare(g, Affine::identity(), 1));
    EXPECT_EQ(sh.at(95, 50).a, 0.0f) << "behind the focal point";
    EXPECT_EQ(sh.at(50, 90).a, 0.0f) << "beside the cone";
    EXPECT_EQ(sh.at(50, 50).a, 1.0f) << "inside the end circle";
    EXPECT_EQ(sh.at(70, 50).a, 1.0f) << "between the circles";
    Premul8 row[4];
    EXPECT_FALSE(sh.store_opaque(0, 50, 4, row));
}

// A focal point on the circle is a cone whichever way rounding puts it:
// 0.4 - 0.1 rounds above 0.3 and 0.4 - 0.7 below, and the two mirror
// images were drawn one as a cone, one as a clamped focus (the review's
// r1.svg). Circles 1e300 wide are measured without overflow (were NaN).
TEST(Gradient, ConesAreDecidedAboveRoundingAndMeasuredWithoutOverflow) {
    GradientShader left, right;
    Gradient a = two_stops(Gradient::Kind::Radial, Spread::Pad), b = a;
    a.center = {0.4, 0.5}, a.radius = 0.3, a.focal = {0.1, 0.5};
    b.center = {0.4, 0.5}, b.radius = 0.3, b.focal = {0.7, 0.5};
    ASSERT_TRUE(left.prepare(a, Affine::scale(100, 100), 1));
    ASSERT_TRUE(right.prepare(b, Affine::scale(100, 100), 1));
    for (int y : {10, 37, 50})
        for (int x = 0; x < 80; ++x) {
            const Premul p = left.at(x, y), q = right.at(79 - x, y);
            EXPECT_NEAR(p.a, q.a, 1e-6) << x << "," << y;
            EXPECT_NEAR(p.r, q.r, 2e-3) << x << "," << y;
        }
    Gradient huge = two_stops(Gradient::Kind::Radial, Spread::Pad);
    huge.center = {1e300, 0}, huge.radius = 1e300, huge.focal = {-1e300, 0};
    GradientShader sh;
    ASSERT_TRUE(sh.prepare(huge, Affine::identity(), 1));
    EXPECT_EQ(sh.at(150, 0).a, 1.0f) << "inside the end circle, near its edge";
}

TEST(Gradient, StopsInterpolateUnpremultipliedAsSvgDoes) {
    // Opaque red to transparent blue: half way, the straight color is purple
    // (0.5, 0, 0.5) at alpha 0.5, as browsers and librsvg draw SVG gradients;
    // premultiplied interpolation would give red at alpha 0.5 and no blue.
    Gradient g = two_stops(Gradient::Kind::Linear, Spread::Pad, {1, 0, 0, 1}, {0, 0, 1, 0});
    g.p1 = {0, 0}, g.p2 = {1023, 0};
    GradientShader sh;
    ASSERT_TRUE(sh.prepare(g, Affine::identity(), 1));
    const Premul mid = sh.at(511, 0);
    EXPECT_NEAR(mid.a, 0.5f, 2e-3f);
    EXPECT_NEAR(mid.r, 0.25f, 2e-3f);
    EXPECT_NEAR(mid.b, 0.25f, 2e-3f);
    EXPECT_EQ(mid.g, 0.0f);
    // Opacity scales the premultiplied color, after interpolation.
    ASSERT_TRUE(sh.prepare(g, Affine::identity(), 0.5f));
    const Premul half = sh.at(511, 0);
    EXPECT_NEAR(half.a, 0.25f, 1e-3f);
    EXPECT_NEAR(half.r, 0.125f, 1e-3f);
}

TEST(Gradient, LinearLightInterpolation) {
    Gradient g = two_stops(Gradient::Kind::Linear, Spread::Pad);
    g.p1 = {0, 0}, g.p2 = {1023, 0};
    g.linear_light = true;
    GradientShader sh;
    ASSERT_TRUE(sh.prepare(g, Affine::identity(), 1));
    // Half way in linear light is sRGB-encoded 0.7354 (not 0.5).
    EXPECT_NEAR(sh.at(511, 0).r, 0.7354f, 3e-3f);
}

TEST(Gradient, SingularMapsAndNoStopsPaintNothing) {
    Gradient g = two_stops(Gradient::Kind::Linear, Spread::Pad);
    GradientShader sh;
    EXPECT_FALSE(sh.prepare(g, Affine::scale(1, 0), 1));
    g.stops.clear();
    EXPECT_FALSE(sh.prepare(g, Affine::identity(), 1));
}

Canvas render(const std::string& svg, std::vector<SvgDiagnostic>* warnings = nullptr) {
    const SvgResult doc = parse_svg(svg, "g.svg");
    EXPECT_TRUE(doc.scene) << doc.error;
    if (warnings) *warnings = doc.warnings;
    Canvas c(int(doc.scene->width), int(doc.scene->height));
    Renderer().render(*doc.scene, Affine::identity(), c, {});
    return c;
}

// Trial `trial`'s gradient of `stops`: linear on even trials, radial on odd
// ones, the spreads in turn, end points, circle and focal point at random in
// a 200 px square, with a focal circle on every fourth trial.
Gradient random_gradient(testing::Rng& rng, int trial, std::vector<GradientStop> stops) {
    const auto kind = trial % 2 ? Gradient::Kind::Radial : Gradient::Kind::Linear;
    Gradient g = two_stops(kind, Spread(trial / 2 % 3));
    g.stops = std::move(stops);
    g.p1 = rng.point(200), g.p2 = rng.point(200);
    g.center = rng.point(200), g.radius = rng.uniform(5, 150);
    g.focal = g.center + Vec2{rng.uniform(-1, 1), rng.uniform(-1, 1)} * (0.5 * g.radius);
    g.focal_radius = trial % 4 == 1 ? rng.uniform(0, 0.25) * g.radius : 0;
    return g;
}

// The identity, or on every third trial a random rotation and scale.
Affine random_map(testing::Rng& rng, int trial) {
    const Affine m = Affine::rotate(rng.uniform(0, 6.28)) * Affine::scale(rng.uniform(0.3, 3));
    return trial % 3 ? Affine::identity() : m;
}

// A row of `shortest` to 300 pixels shaded at once, from a random place.
struct ShadedRow {
    int x, y;
    std::vector<Premul> pixels;
};
ShadedRow shade_random_row(const GradientShader& sh, testing::Rng& rng, int shortest = 1) {
    const int x = rng.integer(-100, 200), y = rng.integer(-100, 200);
    const int n = rng.integer(shortest, 300);
    ShadedRow r{x, y, std::vector<Premul>(std::size_t(n))};
    sh.shade(x, y, n, r.pixels.data());
    return r;
}

TEST(Gradient, RowsShadeTheTableEntryNearestEachPixelsParameter) {
    // Black to white, opaque: table entry k is the gray k / (kGradientLut - 1),
    // so each shaded pixel tells which entry it took.
    testing::Rng rng(17);
    for (int trial = 0; trial < 60; ++trial) {
        const Gradient g = random_gradient(rng, trial, {{0, {0, 0, 0, 1}}, {1, {1, 1, 1, 1}}});
        GradientShader sh;
        ASSERT_TRUE(sh.prepare(g, random_map(rng, trial), 1));
        const auto [x, y, row] = shade_random_row(sh, rng);
        const int n = int(row.size());
        for (int i = 0; i < n; ++i) {
            // The nearest entry to the reference t; a row computes t in another
            // order (from device space, with 1 / a for the radial division),
            // which may round the other way within 1e-9 of a midpoint.
            const double t = sh.parameter({x + i + 0.5, y + 0.5});
            EXPECT_NEAR(row[std::size_t(i)].r * (kGradientLut - 1), t * (kGradientLut - 1),
                        0.5 + 1e-4)
                << "trial " << trial << ", pixel (" << x + i << ", " << y << "), t " << t;
        }
    }
}

// Rows are shaded in blocks, two pixels at a time where the CPU has SSE2,
// and one at a time at a block's odd end: every pixel of a row gets the bits
// that shading it alone (at(), the one-pixel path) gives. Linear and radial,
// with and without a focal circle, every spread, rows across several
// blocks, and geometry whose parameter overflows to NaN (the first stop).
TEST(Gradient, RowsShadeAsEachPixelAlone) {
    testing::Rng rng(19);
    for (int trial = 0; trial < 90; ++trial) {
        // Three stops, translucent, with a hard edge at the end.
        const std::vector<GradientStop> stops = {
            {0, {0.9f, 0.1f, 0.2f, 1}}, {0.6f, {0.1f, 0.3f, 1, 0.5f}}, {1, {0, 1, 0, 1}}};
        Gradient g = random_gradient(rng, trial, stops);
        // t is NaN on every 15th trial, every spread in turn (pad first), on
        // rows long enough for the widest form.
        const bool nan = trial % 15 == 14;
        if (nan) g.p1 = {-1e308, 0}, g.p2 = {1e308, 1}, g.spread = Spread(trial / 15 % 3);
        GradientShader sh;
        ASSERT_TRUE(sh.prepare(g, random_map(rng, trial), 0.8f));
        const auto [x, y, row] = shade_random_row(sh, rng, nan ? 16 : 1);
        const int n = int(row.size());
        for (int i = 0; i < n; ++i) {
            const Premul p = row[std::size_t(i)], q = sh.at(x + i, y);
            EXPECT_TRUE(p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a)
                << "trial " << trial << ", pixel " << i << " of " << n << " from (" << x << ", "
                << y << ")";
        }
    }
}

// Where every stop is opaque and the opacity 1, spans of coverage 1 on an
// 8-bit canvas store the gradient's colors quantized: the canvas comes out
// as each pixel's color composited over a translucent background, byte for
// byte, for every kind and spread, with and without a focal circle, and
// geometry whose parameter is NaN. A translucent stop, or an opacity below
// 1, and nothing is stored (the span composites as before).
TEST(Gradient, OpaqueGradientsStoreTheBytesTheirCompositeGives) {
    testing::Rng rng(23);
    const Premul bg{0.1f, 0.3f, 0.2f, 0.5f};
    for (int trial = 0; trial < 90; ++trial) {
        const bool opaque = trial % 5 != 4, full = trial % 7 != 6;
        std::vector<GradientStop> stops = {
            {0, {0.9f, 0.1f, 0.2f, 1}}, {0.6f, {0.1f, 0.3f, 1, 1}}, {1, {0, 1, 0, 1}}};
        if (!opaque) stops[1].color.a = 0.5f;
        Gradient g = random_gradient(rng, trial, stops);
        if (trial % 15 == 14) g.p1 = {-1e308, 0}, g.p2 = {1e308, 1}; // t is NaN
        GradientShader sh;
        ASSERT_TRUE(sh.prepare(g, random_map(rng, trial), full ? 1.0f : 0.8f));
        const int x = rng.integer(-100, 200), y = rng.integer(-100, 200), n = rng.integer(1, 300);
        std::vector<Premul8> bytes(static_cast<std::size_t>(n));
        const bool stored = sh.store_opaque(x, y, n, bytes.data());
        EXPECT_EQ(stored, opaque && full) << "trial " << trial;
        Canvas8 canvas(n, 1, x, y), expected(n, 1, x, y);
        canvas.fill(bg);
        expected.fill(bg);
        GradientSpanPainter<Premul8>(canvas, sh).span({y, x, n, nullptr, 1.0f});
        for (int i = 0; i < n; ++i) {
            blend_over(expected.row(0)[i], sh.at(x + i, y), 1);
            if (stored) {
                EXPECT_EQ(bytes[std::size_t(i)], expected.row(0)[i]) << "pixel " << i;
            }
            ASSERT_EQ(canvas.row(0)[i], expected.row(0)[i])
                << "trial " << trial << ", pixel " << i << " of " << n << " from (" << x << ", "
                << y << ")";
        }
    }
}

TEST(SvgGradient, BoundingBoxAndUserSpaceUnits) {
    // Black to white across a 100 px wide rect at x = 50: pixel x has t = (x + 0.5 - 50) / 100.
    const std::string units[] = {R"svg(gradientUnits="objectBoundingBox")svg",
                                 R"svg(gradientUnits="userSpaceOnUse" x1="50" x2="150")svg"};
    for (const std::string& u : units) {
        const Canvas c =
            render(R"svg(<svg width="200" height="20"><linearGradient id="g" )svg" + u +
                   R"svg(><stop offset="0" stop-color="black"/><stop offset="1" stop-color="white"/>
            </linearGradient><rect x="50" width="100" height="20" fill="url(#g)"/></svg>)svg");
        for (int x : {50, 75, 100, 149})
            EXPECT_NEAR(c.row(10)[x].r, (float(x) + 0.5f - 50) / 100, 1.5e-3f) << u << " x " << x;
    }
}

TEST(SvgGradient, FocalRadiusIsTheFirstStopsCircle) {
    // fr = 50 about the centre: a disc of radius 50 in the first stop, then
    // black to white out to r = 100 (WPT's radialgradient-basic-002 drew a
    // point there, fr ignored).
    const Canvas c = render(R"svg(<svg width="220" height="220">
        <radialGradient id="g" cx="110" cy="110" r="100" fr="50" gradientUnits="userSpaceOnUse">
        <stop offset="0" stop-color="black"/><stop offset="1" stop-color="white"/></radialGradient>
        <rect width="220" height="220" fill="url(#g)"/></svg>)svg");
    for (const int d : {0, 20, 45, 60, 75, 90}) {
        const float t = std::clamp((float(d) + 0.5f - 50) / 50, 0.0f, 1.0f);
        EXPECT_NEAR(c.row(110)[110 + d].r, t, 2e-3f) << "distance " << d;
    }
}

TEST(SvgGradient, TransformHrefInheritanceAndStops) {
    std::vector<SvgDiagnostic> warnings;
    const Canvas c =
        render(R"svg(<svg xmlns:xlink="http://www.w3.org/1999/xlink" width="100" height="100">
        <linearGradient id="stops"><stop offset="0" stop-color="black"/><stop offset="100%" style="stop-color:#fff"/></linearGradient>
        <linearGradient id="t" xlink:href="#stops" gradientTransform="rotate(90 0.5 0.5)"/>
        <rect width="100" height="100" fill="url(#t)"/></svg>)svg",
               &warnings);
    // Rotated by 90 degrees: the gradient runs downwards; inherited stops.
    EXPECT_NEAR(c.row(10)[50].r, 0.105f, 2e-3f);
    EXPECT_NEAR(c.row(90)[50].r, 0.905f, 2e-3f);
    EXPECT_NEAR(c.row(90)[5].r, c.row(90)[95].r, 1e-6f);
    EXPECT_TRUE(warnings.empty());
}

// resvg's radialGradient/attributes-via-xlink-href-from-linearGradient: a
// linear gradient's cy or fx is no attribute of a linear gradient, so a
// radial one referring to it keeps its own (initial) values; the attributes
// both kinds have (spreadMethod, units, transform, stops) are inherited
// across kinds. Before: centred at y = 10, focal point at x = 0.
TEST(SvgGradient, GeometryIsInheritedFromTheSameKindOnly) {
    std::vector<SvgDiagnostic> warnings;
    const Canvas c = render(R"svg(<svg width="100" height="100">
        <linearGradient id="l" cy="10" fx="0" spreadMethod="reflect" gradientUnits="userSpaceOnUse">
          <stop offset="0" stop-color="white"/><stop offset="1" stop-color="black"/></linearGradient>
        <radialGradient id="r" href="#l" cx="50" r="20"/>
        <rect width="100" height="100" fill="url(#r)"/></svg>)svg",
                            &warnings);
    // Centre (50, 50), r = 20 in user space, reflected: white at 0 and 40 px
    // from the centre, black at 20.
    for (const auto& [x, expect] : {std::pair{50, 0.0f}, {70, 1.0f}, {90, 0.0f}, {30, 1.0f}})
        EXPECT_NEAR(1 - c.row(50)[x].r, expect, 0.05f) << "x " << x;
    EXPECT_TRUE(warnings.empty());
}

// resvg's stroke/gradient-with-objectBoundingBox-and-fallback-on-lines: a
// horizontal line has no box to map objectBoundingBox units onto, so its
// stroke is the fallback color, or none without one. Before: none either way.
TEST(SvgGradient, ObjectBoundingBoxUnitsOnALineTakeTheFallback) {
    const Canvas c = render(R"svg(<svg width="40" height="40">
        <linearGradient id="g"><stop offset="0" stop-color="red"/></linearGradient>
        <line x1="0" y1="10" x2="40" y2="10" stroke="url(#g) #00ff00" stroke-width="4"/>
        <line x1="0" y1="30" x2="40" y2="30" stroke="url(#g)" stroke-width="4"/>
        <line x1="0" y1="20" x2="40" y2="21" stroke="url(#g) #00ff00" stroke-width="4"/></svg>)svg");
    EXPECT_EQ(c.row(10)[20].g, 1.0f);
    EXPECT_EQ(c.row(10)[20].r, 0.0f);
    EXPECT_EQ(c.row(30)[20].a, 0.0f);
    EXPECT_NEAR(c.row(20)[20].r, 1.0f, 1e-6f); // a slanted line has a box: the gradient
}

TEST(SvgGradient, TransparentStopIsTransparentBlack) {
    // SVG interpolates straight colors: white to `transparent` (black at
    // alpha 0) passes through gray at half alpha, as browsers and librsvg
    // draw it; a premultiplied ramp would stay white.
    const Canvas c = render(R"svg(<svg width="100" height="10"><linearGradient id="g">
        <stop offset="0" stop-color="white"/><stop offset="1" stop-color="transparent"/>
        </linearGradient><rect width="100" height="10" fill="url(#g)"/></svg>)svg");
    const Premul mid = c.row(5)[50];
    EXPECT_NEAR(mid.a, 0.495f, 3e-3f);
    EXPECT_NEAR(mid.r, 0.495f * 0.495f, 3e-3f); // gray 0.495 at alpha 0.495
}

TEST(SvgGradient, MissingReferencesFallBackWithAWarning) {
    std::vector<SvgDiagnostic> warnings;
    const Canvas c = render(R"svg(<svg width="30" height="10">
        <linearGradient id="a" href="#gone"><stop offset="0" stop-color="blue"/></linearGradient>
        <rect width="10" height="10" fill="url(#missing) lime"/>
        <rect x="10" width="10" height="10" fill="url(#a)"/>
        <rect x="20" width="10" height="10" fill="url(#nope)"/></svg>)svg",
                            &warnings);
    EXPECT_EQ(c.row(5)[5].g, 1.0f);  // fallback color
    EXPECT_EQ(c.row(5)[15].b, 1.0f); // a's href names nothing: a is used as it is
    EXPECT_EQ(c.row(5)[25].a, 0.0f); // no gradient, no fallback: none
    EXPECT_GE(warnings.size(), 2u);
}

// The located warning whose text contains `what`, or "" (with the list).
std::string find_warning(const SvgResult& r, const std::string& what) {
    std::string all;
    for (const SvgDiagnostic& w : r.warnings) {
        if (w.text().find(what) != std::string::npos) return w.text();
        all += "\n  " + w.text();
    }
    ADD_FAILURE() << "no warning with '" << what << "' among:" << all;
    return "";
}

TEST(SvgGradient, HrefCyclesAndOverlongChainsEndTheChainThereWithAWarning) {
    const std::string cycle_svg = R"svg(<svg width="30" height="10">
        <linearGradient id="a" href="#b"><stop offset="0" stop-color="blue"/></linearGradient>
        <linearGradient id="b" href="#a"/>
        <rect width="10" height="10" fill="url(#b)"/></svg>)svg";
    const SvgResult cycle = parse_svg(cycle_svg, "c.svg");
    ASSERT_TRUE(cycle.scene) << cycle.error;
    // b takes a's stops; the chain ends at a's link back to b.
    const Fill& fill = *std::get<Shape>(cycle.scene->root.children.at(0).item).fill;
    ASSERT_TRUE(fill.gradient);
    EXPECT_EQ(fill.gradient->stops.at(0).color, (Rgba{0, 0, 1, 1}));
    find_warning(cycle, "c.svg:2: <linearGradient>: href '#b' makes a cycle");
    SvgOptions strict;
    strict.strict = true;
    const SvgResult refused = parse_svg(cycle_svg, "c.svg", strict);
    EXPECT_FALSE(refused.scene);
    EXPECT_NE(refused.error.find("c.svg:2: <linearGradient>: href '#b' makes a cycle"),
              std::string::npos)
        << refused.error;
    std::string chain = "<svg width='1' height='1'>";
    for (int i = 0; i < 100; ++i)
        chain += "<linearGradient id='g" + std::to_string(i) + "' href='#g" +
                 std::to_string(i + 1) + "'/>\n";
    chain += "<linearGradient id='g100'/><rect width='1' height='1' fill='url(#g0)'/></svg>";
    const SvgResult long_chain = parse_svg(chain, "l.svg");
    ASSERT_TRUE(long_chain.scene) << long_chain.error;
    find_warning(long_chain, "l.svg:64: <linearGradient>: the href chain is longer than 64");
}

// The shader keeps its color table for the gradient it last built: a second
// scene through the same renderer must not be painted with the first one's.
TEST(SvgGradient, OneRendererForSeveralScenesUsesEachScenesGradient) {
    Renderer r;
    for (const char* color : {"red", "blue", "lime"}) {
        const SvgResult doc =
            parse_svg(std::string(R"svg(<svg width="10" height="10"><linearGradient id="g">
            <stop offset="0" stop-color=")svg") +
                          color + R"svg("/></linearGradient>
            <rect width="10" height="10" fill="url(#g)"/></svg>)svg",
                      "s.svg");
        ASSERT_TRUE(doc.scene) << doc.error;
        Canvas c(10, 10);
        r.render(*doc.scene, Affine::identity(), c, {});
        const Rgba want = *parse_color(color);
        EXPECT_EQ(c.row(5)[5].r, want.r) << color;
        EXPECT_EQ(c.row(5)[5].g, want.g) << color;
        EXPECT_EQ(c.row(5)[5].b, want.b) << color;
    }
}

TEST(SvgGradient, InvalidValuesTakeTheirInitialValueWithAWarning) {
    // spreadMethod wobble: pad; gradientUnits bogus: objectBoundingBox; the
    // stop offset x: 0. So a red-to-blue ramp across the rect, padded.
    const SvgResult r = parse_svg(R"svg(<svg width="100" height="10">
        <linearGradient id="g" spreadMethod="wobble" gradientUnits="bogus" x2="0.5">
        <stop offset="x" stop-color="red"/><stop offset="1" stop-color="blue"/></linearGradient>
        <rect width="100" height="10" fill="url(#g)"/></svg>)svg",
                                  "m.svg");
    ASSERT_TRUE(r.scene) << r.error;
    find_warning(r, "m.svg:2: <linearGradient>: spreadMethod: 'wobble' is invalid; pad is used");
    find_warning(r, "m.svg:2: <linearGradient>: gradientUnits: 'bogus'");
    find_warning(r, "m.svg:3: <stop>: offset: 'x' is not a number; 0 is used");
    Canvas c(100, 10);
    Renderer().render(*r.scene, Affine::identity(), c, {});
    EXPECT_NEAR(c.row(5)[0].r, 1.0f, 0.02f);   // offset 0: red
    EXPECT_NEAR(c.row(5)[25].r, 0.49f, 0.02f); // halfway to x2 = 0.5 of the box
    EXPECT_EQ(c.row(5)[75].b, 1.0f);           // padded beyond x2
}

} // namespace
} // namespace casteljau
