// Stroke outlines' coverage: the pixels at inner corners (each covered 3/4,
// once), random polylines and closed polygons against a sampled union of
// their parts (segment bands, joins, caps), and closed subpaths cut by the
// visible box keeping their closing join.
#include "casteljau/curve/path_data.h"
#include "casteljau/render/renderer.h"
#include "casteljau/stroke/stroker.h"
#include "casteljau/svg/reader.h"
#include "check.h"
#include "corpus.h"
#include "coverage.h"
#include "stroke_cases.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace casteljau {
namespace {

constexpr double kPi = std::numbers::pi;
using testing::area;
using testing::cover;
using testing::parse;
using testing::style;

// Rendered through the library (parse_svg, Renderer), as the CLI renders.
Canvas render_svg(const std::string& svg) {
    const SvgResult doc = parse_svg(svg, "t.svg");
    EXPECT_TRUE(doc.scene) << doc.error;
    Canvas c(int(doc.scene->width), int(doc.scene->height));
    if (doc.scene) Renderer().render(*doc.scene, Affine::identity(), c, {});
    return c;
}

// <path d="M5 5 H75 V75" stroke="#000"/> drew alpha 1 at pixel (74,5), where
// the stroke covers 3/4 of it (librsvg: 192/255): the inner side of a join
// went through the joint, so the two segments' bands overlapped there with
// winding 2, which exact-area coverage (min(|winding integrated over the
// pixel|, 1)) counted twice in the pixels it shares with winding 0; so at
// every inner corner of a stroked rect. Now the inner offsets meet at the
// inner corner. With the corner at a pixel centre, for widths 1, 2 and 3.3
// and every join, turning right and left, open, closed by a rect and by Z
// (the closing join), and along a dash (through a rect's start too, where
// the first and last dashes had caps): that pixel is covered 3/4.
TEST(Stroker, InnerCornerPixelsOfAStrokedPolylineAndRectAreThreeQuarters) {
    for (const double w : {1.0, 2.0, 3.3})
        for (const char* join : {"miter", "round", "bevel"}) {
            // The path's corners at 10.5 - h and 69.5 + h: the inner corners
            // are the centres of pixels 10 and 69.
            const double h = w / 2, lo = 10.5 - h, hi = 69.5 + h;
            const std::string a = std::to_string(lo), b = std::to_string(hi);
            const std::string size = std::to_string(hi - lo);
            const std::vector<std::pair<int, int>> all = {{10, 10}, {69, 10}, {69, 69}, {10, 69}};
            const std::pair<std::string, std::vector<std::pair<int, int>>> cases[] = {
                {"<path d='M" + a + " " + a + " H" + b + " V" + b + "'", {{69, 10}}},
                {"<path d='M" + a + " " + a + " V" + b + " H" + b + "'", {{10, 69}}},
                {"<rect x='" + a + "' y='" + a + "' width='" + size + "' height='" + size + "'",
                 all},
                {"<path d='M" + a + " " + a + " V" + b + " H" + b + " V" + a + " Z'", all},
                {"<path stroke-dasharray='100 5' d='M" + a + " " + a + " H" + b + " V" + b + "'",
                 {{69, 10}}},
                // Dashes [0, 50), [55, 155), [160, 260) on a rect 240 to 249
                // long: the first and last go on through the closing join.
                {"<rect stroke-dasharray='100 5' stroke-dashoffset='50' x='" + a + "' y='" + a +
                     "' width='" + size + "' height='" + size + "'",
                 all},
            };
            for (const auto& [shape, corners] : cases) {
                const std::string svg =
                    "<svg xmlns='http://www.w3.org/2000/svg' width='80' height='80'>" + shape +
                    " fill='none' stroke='#000' stroke-width='" + std::to_string(w) +
                    "' stroke-linejoin='" + join + "'/></svg>";
                const Canvas c = render_svg(svg);
                for (const auto& [x, y] : corners)
                    EXPECT_NEAR(c.row(y)[x].a, 0.75, 1e-3) << svg << " at pixel " << x << "," << y;
            }
        }
}

Polygon counterclockwise(Polygon p) { // positive area, so that overlapping pieces add up
    if (area(p) < 0) std::reverse(p.begin(), p.end());
    return p;
}

Polygon disc(Point c, double r) { // 128 sides: within 1e-3 px of the circle for r <= 3
    Polygon p;
    for (int i = 0; i < 128; ++i)
        p.push_back(c + Vec2{std::cos(i * kPi / 64), std::sin(i * kPi / 64)} * r);
    return p;
}

// A random stroke whose parts overlap only next to its joints, for
// comparison with the union of its parts: each segment's band, a piece per
// join and a cap at each open end, built from SVG 1.1, 11.4 and not by the
// stroker (but for curved segments' bands, each stroked alone: no joins).
struct PartsCase {
    Path path;
    StrokeGeometry st;
    std::vector<Polygon> parts;
};

// The join at p from unit tangent d0 to d1: a round join is a disc of radius
// h at the joint (the bands cover what of it is not the arc's sector); a
// miter the quadrilateral up to the outer offset lines' crossing while the
// miter ratio 1 / sin(theta/2), theta the angle between the segments, is
// within the limit; otherwise, or a bevel, the triangle across the outer
// offsets' ends.
void add_join(std::vector<Polygon>& out, Point p, Vec2 d0, Vec2 d1, const StrokeGeometry& st) {
    const double h = st.width / 2;
    if (st.join == LineJoin::Round) return out.push_back(disc(p, h));
    const double outer = d0.cross(d1) > 0 ? -1 : 1; // the left side (perp) is inner on a left turn
    const Point a = p + d0.perp() * (outer * h), b = p + d1.perp() * (outer * h);
    Polygon piece{p, a};
    const double theta = kPi - std::acos(std::clamp(d0.dot(d1), -1.0, 1.0));
    if (st.join == LineJoin::Miter && 1 / std::sin(theta / 2) <= st.miter_limit)
        piece.push_back(a + d0 * ((b - a).cross(d1) / d0.cross(d1))); // on both offset lines
    piece.push_back(b);
    out.push_back(counterclockwise(piece));
}

// The cap at the end e of an open subpath, d the unit tangent out of it.
void add_cap(std::vector<Polygon>& out, Point e, Vec2 d, const StrokeGeometry& st) {
    const double h = st.width / 2;
    const Vec2 n = d.perp() * h;
    if (st.cap == LineCap::Round) out.push_back(disc(e, h));
    if (st.cap == LineCap::Square)
        out.push_back(counterclockwise({e + n, e + n + d * h, e - n + d * h, e - n}));
}

// Distance between the segments ab and cd (0 where they cross).
double segment_distance(Point a, Point b, Point c, Point d) {
    const double ab_c = (b - a).cross(c - a), ab_d = (b - a).cross(d - a);
    const double cd_a = (d - c).cross(a - c), cd_b = (d - c).cross(b - c);
    if (ab_c * ab_d < 0 && cd_a * cd_b < 0) return 0;
    return std::min({distance_to_segment(a, c, d), distance_to_segment(b, c, d),
                     distance_to_segment(c, a, b), distance_to_segment(d, a, b)});
}

// A random stroke through 3 to 6 points (kind 0: a walk turning by +-90
// degrees from an axis; 1: a walk turning by any angle below 160 degrees; 2:
// a closed star-shaped polygon, turning both ways), its segments lines or,
// when `curved`, cubics bowed by up to a fifth of their chord. Rejected
// (nullopt) unless the union of its parts is the stroke with overlaps next
// to the joints only: segments that are not neighbours more than twice the
// stroke's reach (and a pixel) apart, every point that far inside the
// image, every turn below 160 degrees, every segment longer than the
// stretches h tan(turn/2) from its ends where the inner offsets meet, and
// (curves) a radius of curvature at least 2h, so that the inner offset does
// not fold.
std::optional<PartsCase> random_parts_case(testing::Rng& rng, int kind, bool curved, int size) {
    PartsCase c;
    StrokeGeometry& st = c.st;
    st = style(rng.log_uniform(0.5, 6),
               std::array{LineCap::Butt, LineCap::Round, LineCap::Square}[rng.integer(0, 2)],
               std::array{LineJoin::Miter, LineJoin::Round, LineJoin::Bevel}[rng.integer(0, 2)]);
    st.miter_limit = std::array{1.5, 4.0, 10.0}[rng.integer(0, 2)];
    const double h = st.width / 2;
    const double reach =
        h * std::max(st.join == LineJoin::Miter ? st.miter_limit : 1.0, std::sqrt(2.0)) + 1;
    std::vector<Point> v;
    if (kind < 2) {
        double heading = kind == 0 ? kPi / 2 * rng.integer(0, 3) : rng.uniform(0, 2 * kPi);
        v.push_back(rng.point(size));
        for (int i = rng.integer(2, 5); i > 0; --i) {
            v.push_back(v.back() +
                        Vec2{std::cos(heading), std::sin(heading)} * rng.uniform(10, 70));
            heading += kind == 0 ? (rng.integer(0, 1) ? 1 : -1) * kPi / 2 : rng.uniform(-2.8, 2.8);
        }
    } else {
        std::vector<double> angles;
        for (int i = rng.integer(3, 6); i > 0; --i) angles.push_back(rng.uniform(0, 2 * kPi));
        std::sort(angles.begin(), angles.end());
        for (const double t : angles)
            v.push_back(Point{size / 2.0, size / 2.0} +
                        Vec2{std::cos(t), std::sin(t)} * rng.uniform(15, 60));
    }
    const bool closed = kind == 2;
    const std::size_t n = closed ? v.size() : v.size() - 1;
    std::vector<CubicBez> segs;
    for (std::size_t i = 0; i < n; ++i) {
        const Point a = v[i], b = v[(i + 1) % v.size()];
        const Vec2 bow = (b - a).perp() * (curved ? 0.2 : 0.0);
        segs.push_back({{a, lerp(a, b, 1.0 / 3) + bow * rng.uniform(-1, 1),
                         lerp(a, b, 2.0 / 3) + bow * rng.uniform(-1, 1), b}});
    }
    const auto d0 = [&](std::size_t i) { return (segs[i].p[1] - segs[i].p[0]).normalized(); };
    const auto d1 = [&](std::size_t i) { return (segs[i].p[3] - segs[i].p[2]).normalized(); };
    std::vector<std::vector<Point>> pts(n);
    std::vector<double> len(n, 0.0), foot(n + 1, 0.0); // foot[i]: at the joint before segment i
    for (std::size_t i = 0; i < n; ++i) {
        for (int k = 0; k <= 32; ++k) pts[i].push_back(segs[i].eval(k / 32.0));
        for (int k = 0; k < 32; ++k) len[i] += distance(pts[i][k], pts[i][k + 1]);
        for (int k = 0; curved && k <= 200; ++k) {
            const Vec2 e1 = segs[i].deriv(k / 200.0), e2 = segs[i].deriv2(k / 200.0);
            if (std::pow(e1.length(), 3) < 2 * h * std::fabs(e1.cross(e2))) return std::nullopt;
        }
        for (const Point p : pts[i])
            if (p.x < reach || p.x > size - reach || p.y < reach || p.y > size - reach)
                return std::nullopt;
        if (i == 0 && !closed) continue;
        const double turn = std::acos(std::clamp(d1((i + n - 1) % n).dot(d0(i)), -1.0, 1.0));
        if (turn > 160 * kPi / 180) return std::nullopt;
        foot[i] = h * std::tan(turn / 2);
    }
    foot[n] = closed ? foot[0] : 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (len[i] < foot[i] + foot[i + 1] + h) return std::nullopt;
        for (std::size_t j = i + 2; j < n; ++j)
            for (std::size_t k = 0; k + 1 < pts[i].size() && !(closed && i == 0 && j == n - 1); ++k)
                for (std::size_t l = 0; l + 1 < pts[j].size(); ++l)
                    if (segment_distance(pts[i][k], pts[i][k + 1], pts[j][l], pts[j][l + 1]) <
                        2 * reach)
                        return std::nullopt;
    }
    c.path.move_to(v[0]);
    for (std::size_t i = 0; i < n; ++i) {
        const CubicBez& s = segs[i];
        if (curved)
            c.path.cubic_to(s.p[1], s.p[2], s.p[3]);
        else if (!closed || i + 1 < n)
            c.path.line_to(s.p[3]);
        Path alone; // the band: butt ends, no joins
        alone.move_to(s.p[0]);
        alone.cubic_to(s.p[1], s.p[2], s.p[3]);
        std::vector<Polygon> band;
        stroke_outline(alone, style(st.width), 0.01, band);
        for (const Polygon& p : band) c.parts.push_back(counterclockwise(p));
        if (i > 0 || closed) add_join(c.parts, s.p[0], d1((i + n - 1) % n), d0(i), st);
    }
    if (closed) c.path.close();
    if (!closed) {
        add_cap(c.parts, v.front(), -d0(0), st);
        add_cap(c.parts, v.back(), d1(n - 1), st);
    }
    return c;
}

// The largest difference between the exact-area coverage (nonzero: as the
// renderer fills it) of the case's stroke outline and that of the union of
// its parts (sampled 256 x 256 per pixel, where overlaps do not matter), the
// outline built whole and, as the renderer builds it, per strip of 16 rows
// from a visible box a pixel larger, which cuts closed subpaths elsewhere.
struct Worst {
    float difference = 0;
    int x = 0, y = 0;
    bool strips = false;
};

Worst worst_difference(const PartsCase& c, int size) {
    const std::vector<float> want =
        testing::supersampled_coverage(c.parts, FillRule::NonZero, size, size);
    Worst worst;
    const auto compare = [&](const std::vector<Polygon>& outline, int y0, int y1, bool strips) {
        const testing::CoverageImage got = cover(outline, size, size);
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < size; ++x)
                if (const float d = std::fabs(got.at(x, y) - want[std::size_t(y * size + x)]);
                    d > worst.difference)
                    worst = {d, x, y, strips};
    };
    std::vector<Polygon> whole;
    stroke_outline(c.path, c.st, 0.01, whole);
    compare(whole, 0, size, false);
    for (int y0 = 0; y0 < size; y0 += 16) {
        std::vector<Polygon> strip;
        stroke_outline(c.path, c.st, 0.01, strip, Rect{-1, y0 - 1.0, size + 1.0, y0 + 17.0});
        compare(strip, y0, y0 + 16, true);
    }
    return worst;
}

// Random strokes of polylines and of chains of cubics, open (turning by
// right angles or any angle) and closed (turning both ways), with random
// widths, joins, miter limits and caps: the outline's exact-area coverage
// is, in every pixel, that of the union of the segments' bands, the joins
// and the caps, to 0.01 (the reference's sampling, and the round joins' and
// caps' chords at tolerance 0.01). Through the joint, the inner corners were
// off by up to 1/4, more at sharp turns, where the overlap is larger; and
// strips that cut a closed subpath elsewhere gave its start caps instead of
// the closing join.
TEST(Stroker, RandomStrokesCoverTheUnionOfTheirParts) {
    testing::Rng rng(4242);
    constexpr int size = 128;
    for (int k = 0; k < 42; ++k) {
        const int kind = k % 3;
        const bool curved = k % 2;
        std::optional<PartsCase> c;
        for (int tries = 0; tries < 1000 && !c; ++tries)
            c = random_parts_case(rng, kind, curved, size);
        ASSERT_TRUE(c) << "case " << k;
        const Worst w = worst_difference(*c, size);
        EXPECT_LE(w.difference, 0.01f)
            << "case " << k << " (kind " << kind << (curved ? ", curved" : "") << ") width "
            << c->st.width << " join " << int(c->st.join) << " cap " << int(c->st.cap)
            << ": at pixel " << w.x << "," << w.y << (w.strips ? " (in strips)" : "");
    }
}

// A closed subpath cut by the visible box (by the renderer's strip of 128
// rows, where a 300 px triangle leaves it) was outlined as open parts: its
// start got caps instead of the closing join (the apex lost its miter), and
// a line wholly outside the box did not count as a cut, so the parts were
// closed by a line across the drawing. Within the box, the outline built
// for it now covers what the whole outline covers.
TEST(Stroker, ClosedSubpathsCutByTheVisibleBoxKeepTheirClosingJoin) {
    const struct {
        const char* d;
        double width;
        int w, h; // the box: [0, w] x [0, h], and a pixel more
    } cases[] = {
        {"M150 20 L280 280 L20 280 Z", 20, 300, 128},
        {"M50 50 C 80 50, 120 50, 150 50 L 150 80 C 120 80, 80 80, 50 80 Z", 2, 100, 100},
    };
    for (const auto& c : cases) {
        std::vector<Polygon> whole, part;
        stroke_outline(parse(c.d), style(c.width), 0.25, whole);
        stroke_outline(parse(c.d), style(c.width), 0.25, part, Rect{-1, -1, c.w + 1.0, c.h + 1.0});
        const testing::CoverageImage a = cover(whole, c.w, c.h), b = cover(part, c.w, c.h);
        for (int y = 0; y < c.h; ++y)
            for (int x = 0; x < c.w; ++x)
                ASSERT_NEAR(b.at(x, y), a.at(x, y), 1e-4f) << c.d << " at " << x << "," << y;
    }
}

TEST(Stroker, HairlineCoverageMatchesWidthTimesLength) {
    // 0.3 px wide strokes, horizontal and diagonal: the sum of coverage is
    // width x length, and no pixel along the line is left empty.
    for (const char* d : {"M10 20.3 L90 20.3", "M10 10 L70 70"}) {
        const SvgResult doc =
            parse_svg(std::string(R"svg(<svg width="100" height="100"><path d=")svg") + d +
                          R"svg(" stroke="black" stroke-width="0.3"/></svg>)svg",
                      "h.svg");
        ASSERT_TRUE(doc.scene) << doc.error;
        Canvas c(100, 100);
        Renderer().render(*doc.scene, Affine::identity(), c, {});
        double sum = 0;
        for (int y = 0; y < 100; ++y)
            for (int x = 0; x < 100; ++x) sum += c.row(y)[x].a;
        const double length =
            std::string(d).find("90") != std::string::npos ? 80 : 60 * std::sqrt(2.0);
        // One-pixel-wide stroke at 0.3 opacity, plus the caps' share.
        EXPECT_NEAR(sum, 0.3 * length, 0.3 * 1.5) << d;
    }
}

} // namespace
} // namespace casteljau
