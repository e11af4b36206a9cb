#include "casteljau/curve/path_data.h"

#include <cmath>
#include <gtest/gtest.h>

namespace casteljau {
namespace {

std::vector<Point> ends(const Path& p) {
    std::vector<Point> out;
    for (const Subpath& s : p.subpaths()) {
        out.push_back(s.start);
        for (const Segment& seg : s.segments) out.push_back(segment_end(seg));
    }
    return out;
}

Path parse_ok(std::string_view d) {
    PathDataResult r = parse_path_data(d);
    EXPECT_FALSE(r.error) << "'" << d << "': offset " << r.error->offset << ": "
                          << r.error->message;
    return std::move(r.path);
}

TEST(PathData, EveryCommandAbsoluteAndRelative) {
    const Path p =
        parse_ok("M10 20 L30 20 H40 V30 C40 40 50 40 50 30 S60 20 60 30 Q70 40 80 30 "
                 "T100 30 A10 10 0 0 1 120 30 Z "
                 "m5 5 l10 0 h5 v5 c0 5 5 5 5 0 s5 -5 5 0 q5 5 10 0 t10 0 a5 5 0 0 0 10 0 z");
    ASSERT_EQ(p.subpaths().size(), 2u);
    EXPECT_EQ(p.subpaths()[0].start, (Point{10, 20}));
    EXPECT_TRUE(p.subpaths()[0].closed);
    // The relative subpath starts at the first subpath's start + (5, 5).
    EXPECT_EQ(p.subpaths()[1].start, (Point{15, 25}));
    const auto& segs = p.subpaths()[0].segments;
    EXPECT_EQ(segment_end(segs[1]), (Point{40, 20}));
    EXPECT_EQ(segment_end(segs[2]), (Point{40, 30}));
    // S reflects the previous cubic's second control point (40 40 -> 60 20).
    const auto& s = std::get<CubicBez>(segs[4]);
    EXPECT_EQ(s.p[1], (Point{50, 20}));
    // T reflects the previous quadratic's control point about (80, 30).
    const auto& t = std::get<QuadBez>(segs[6]);
    EXPECT_EQ(t.p[1], (Point{90, 20}));
    EXPECT_EQ(segment_end(p.subpaths()[1].segments[1]), (Point{30, 25}));
}

TEST(PathData, CompactNumbersAndImplicitRepeats) {
    // "M1.5.5" is (1.5, .5); "-1-2" two numbers; exponents; a moveto's extra
    // pairs are linetos; a repeated command letter may be omitted.
    const Path p = parse_ok("M1.5.5 2-1e1 3E+0,4 L5 6 7 8l1 1-1-1");
    EXPECT_EQ(ends(p),
              (std::vector<Point>{{1.5, 0.5}, {2, -10}, {3, 4}, {5, 6}, {7, 8}, {8, 9}, {7, 8}}));
    const Path q = parse_ok("M0,0C1,1,2,2,3,3,4,4,5,5,6,6");
    EXPECT_EQ(q.segment_count(), 2u);
}

TEST(PathData, ArcFlagsWithoutSeparators) {
    const Path p = parse_ok("M0 0a1 1 0 00 10 0A5,5,0,1,1,0,0");
    EXPECT_EQ(ends(p).back(), (Point{0, 0}));
    const Path q = parse_ok("M0 0a5 5 0 1110 0");
    EXPECT_EQ(ends(q).back(), (Point{10, 0}));
}

TEST(PathData, SmoothCurveWithoutPredecessorUsesCurrentPoint) {
    const Path p = parse_ok("M10 10 S20 20 30 10 T 50 10");
    const auto& s = std::get<CubicBez>(p.subpaths()[0].segments[0]);
    EXPECT_EQ(s.p[1], (Point{10, 10}));
    const auto& t = std::get<QuadBez>(p.subpaths()[0].segments[1]);
    EXPECT_EQ(t.p[1], (Point{30, 10}));
}

struct BadCase {
    const char* data;
    std::size_t offset;
    const char* message_part;
    std::size_t segments_kept;
};

// Checks the error and what was kept; returns the kept path's control bounds.
Rect expect_error(const BadCase& c) {
    const PathDataResult r = parse_path_data(c.data);
    EXPECT_TRUE(r.error) << c.data;
    if (!r.error) return {};
    EXPECT_EQ(r.error->offset, c.offset) << c.data << ": " << r.error->message;
    EXPECT_NE(r.error->message.find(c.message_part), std::string::npos)
        << c.data << ": " << r.error->message;
    EXPECT_EQ(r.path.segment_count(), c.segments_kept) << c.data;
    return r.path.empty() ? Rect{} : r.path.control_bounds();
}

TEST(PathData, MalformedDataReportsOffsetAndKeepsWhatCameBefore) {
    const BadCase cases[] = {
        {"L10 10", 0, "moveto", 0},
        {"M0 0 L10", 8, "end of the data", 0},
        {"M0 0 L10 10 L20 x", 16, "found 'x'", 1},
        {"M0 0 L1e 5", 7, "exponent", 0},
        {"M0 0 L1e999 5", 6, "out of range", 0},
        {"M0 0 A5 5 0 2 0 10 0", 12, "arc flag", 0},
        {"M0 0 L10 10 K", 12, "unknown command 'K'", 1},
        {"M0 0 L.e5 1", 6, "expected a number", 0},
        {"M0 0 L10 10,", 12, "after ','", 1},
    };
    for (const BadCase& c : cases) expect_error(c);
}

// Found by fuzz_path_data (tests/fuzz/regressions/path_data): each number
// is finite, their sum is not. Every way of adding coordinates is covered.
TEST(PathData, RelativeSumOverflowingToInfinityIsAnError) {
    const BadCase cases[] = {
        {"M 1e308 1e308 l 1e308 0", 16, "overflow", 0},
        {"M1e308 0 h1e308", 10, "overflow", 0},
        {"M0 -1e308 L0 0 v-1e308 v -1e308", 25, "overflow", 2},
        {"M0 0 C0 0 -1e308 0 1e308 0 S 0 0 0 0", 29, "overflow", 1},
        {"M0 0 Q-1e308 0 1e308 0 T 0 0", 25, "overflow", 1},
        {"m1e308 0 1e308 0", 9, "overflow", 0},
        {"M0 0 A1e308 1e308 0 0 1 1e308 0", 6, "double range", 0},
    };
    for (const BadCase& c : cases) {
        const Rect kept = expect_error(c);
        EXPECT_TRUE(std::isfinite(kept.x0) && std::isfinite(kept.x1)) << c.data;
    }
}

// Radii whose squares underflow to zero once gave Lambda = 0/0 and an arc
// of 1e-300 radius; F.6.6 scales them up to the half circle on the chord.
TEST(PathData, TinyArcRadiiScaleUpToAHalfCircle) {
    const Path p = parse_ok("M0 0 A1e-300 1e-300 0 0 1 1 0");
    ASSERT_GT(p.segment_count(), 0u);
    for (double u = 0; u <= double(p.segment_count()); u += 0.125)
        EXPECT_NEAR(distance(p.eval(0, u), (Point{0.5, 0})), 0.5, 1e-12) << "u = " << u;
    EXPECT_NEAR(p.bounds().y0, -0.5, 1e-12); // sweep 1 from (0,0) to (1,0) runs through y < 0
}

TEST(PathData, UnderflowIsZeroNotAnError) {
    const Path p = parse_ok("M0 0 L1e-400 5");
    EXPECT_EQ(ends(p).back(), (Point{0, 5}));
}

TEST(PathData, EmptyAndWhitespaceOnlyAreValidAndEmpty) {
    EXPECT_TRUE(parse_ok("").empty());
    EXPECT_TRUE(parse_ok(" \t\n").empty());
}

} // namespace
} // namespace casteljau
