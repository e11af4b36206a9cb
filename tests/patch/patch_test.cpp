// Patches: the two evaluations agree, corners interpolate, derivatives match
// finite differences, normals are unit and outward (also at poles), splits
// and subpatches reproduce the surface, B-spline pieces equal their Bezier
// conversion.
#include "casteljau/patch/bspline_patch.h"
#include "casteljau/patch/grid.h"
#include "casteljau/patch/normal.h"
#include "check.h"
#include "patch_models.h"

#include <gtest/gtest.h>
#include <random>

namespace casteljau {
namespace {

// Relative to the control points' scale (100): 1e-12 of it is rounding.
constexpr double kEps = 1e-10;

void expect_near(const PatchPoint& a, const PatchPoint& b, double eps, const char* what) {
    EXPECT_LE(distance(a.p, b.p), eps) << what << ": " << a.p << " vs " << b.p;
    EXPECT_LE(distance(a.st, b.st), eps * 1e-2) << what;
}

// Calls check(patch, u, v) on `trials` seeded random patches, each at a
// random (u, v) in [lo, hi]^2.
template <class Patch, class Check>
void at_random_points(unsigned seed, int trials, double lo, double hi, Check check) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> t(lo, hi);
    for (int trial = 0; trial < trials; ++trial) {
        const auto p = test::random_patch<Patch>(rng);
        const double u = t(rng), v = t(rng);
        check(p, u, v);
    }
}

template <class Patch>
class BezierPatchTest : public ::testing::Test {};
using BezierKinds = ::testing::Types<BilinearPatch, QuadPatch, CubicPatch, BezierPatch<1, 3>>;
TYPED_TEST_SUITE(BezierPatchTest, BezierKinds);

TYPED_TEST(BezierPatchTest, DeCasteljauEqualsMatrixForm) {
    at_random_points<TypeParam>(1, 200, 0, 1, [](const auto& p, double u, double v) {
        expect_near(p.eval(u, v), p.eval_matrix(u, v), kEps, "eval vs matrix");
    });
}

TYPED_TEST(BezierPatchTest, CornersInterpolateExactly) {
    std::mt19937 rng(2);
    const auto p = test::random_patch<TypeParam>(rng);
    constexpr int M = TypeParam::kDegreeU, N = TypeParam::kDegreeV;
    EXPECT_EQ(p.eval(0, 0), p.c[0][0]);
    EXPECT_EQ(p.eval(1, 0), p.c[0][M]);
    EXPECT_EQ(p.eval(0, 1), p.c[N][0]);
    EXPECT_EQ(p.eval(1, 1), p.c[N][M]);
}

TYPED_TEST(BezierPatchTest, DerivativesMatchFiniteDifferences) {
    at_random_points<TypeParam>(3, 100, 0.01, 0.99, [](const auto& p, double u, double v) {
        const double h = 1e-5;
        const auto d = p.derivatives(u, v);
        const auto at = [&](double a, double b) { return p.eval(a, b).p; };
        const Vec3 du = (at(u + h, v) - at(u - h, v)) / (2 * h);
        const Vec3 dv = (at(u, v + h) - at(u, v - h)) / (2 * h);
        const Vec3 duv =
            ((at(u + h, v + h) - at(u - h, v + h)) - (at(u + h, v - h) - at(u - h, v - h))) /
            (4 * h * h);
        EXPECT_LE((d.du - du).length(), 1e-5) << "u " << u << " v " << v;
        EXPECT_LE((d.dv - dv).length(), 1e-5) << "u " << u << " v " << v;
        EXPECT_LE((d.duv - duv).length(), 1e-2) << "u " << u << " v " << v;
        expect_near(d.point, p.eval(u, v), kEps, "point of derivatives");
    });
}

TYPED_TEST(BezierPatchTest, SplitsAndSubpatchesReproduceTheSurface) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> t(0, 1);
    for (int trial = 0; trial < 50; ++trial) {
        const auto p = test::random_patch<TypeParam>(rng);
        const double s = t(rng), u = t(rng), v = t(rng);
        const auto [left, right] = p.split_u(s);
        expect_near(left.eval(u, v), p.eval(s * u, v), kEps, "split_u left");
        expect_near(right.eval(u, v), p.eval(s + (1 - s) * u, v), kEps, "split_u right");
        const auto [low, high] = p.split_v(s);
        expect_near(low.eval(u, v), p.eval(u, s * v), kEps, "split_v low");
        expect_near(high.eval(u, v), p.eval(u, s + (1 - s) * v), kEps, "split_v high");
        const auto sub = p.subpatch(0.2, 0.7, 0.9, 0.4);
        expect_near(sub.eval(u, v), p.eval(0.2 + 0.5 * u, 0.9 - 0.5 * v), 1e-9, "subpatch");
        // The split keeps the outer rows bit for bit: what shared edges rely on.
        EXPECT_EQ(left.c[0][0], p.c[0][0]);
        EXPECT_EQ(low.c[0], p.c[0]);
    }
}

TYPED_TEST(BezierPatchTest, NormalsAreUnitAndAlongTheCrossProduct) {
    at_random_points<TypeParam>(5, 100, 0, 1, [](const auto& p, double u, double v) {
        const Vec3 n = patch_normal(p, u, v);
        const auto d = p.derivatives(u, v);
        EXPECT_NEAR(n.length(), 1.0, 1e-12);
        EXPECT_GT(n.dot(d.du.cross(d.dv)), 0);
    });
}

TEST(BezierPatch, DegreeElevationKeepsTheSurface) {
    std::mt19937 rng(6);
    const auto p = test::random_patch<BezierPatch<1, 2>>(rng);
    const CubicPatch e = elevate_v(elevate_u(elevate_u(p)));
    for (double u : {0.0, 0.3, 1.0})
        for (double v : {0.0, 0.6, 1.0}) expect_near(e.eval(u, v), p.eval(u, v), kEps, "elevated");
}

TEST(BSplinePatch, EqualsItsBezierConversion) {
    at_random_points<BSplinePatch>(7, 200, 0, 1, [](const BSplinePatch& b, double u, double v) {
        expect_near(b.eval_matrix(u, v), b.to_bezier().eval(u, v), kEps, "bspline vs bezier");
        expect_near(b.eval_matrix(u, v), b.to_bezier().eval_matrix(u, v), kEps, "two matrices");
    });
}

TEST(BSplinePatch, GridPiecesMeetContinuously) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> x(-10, 10);
    std::vector<PatchPoint> grid(5 * 6);
    for (PatchPoint& q : grid) q = {{x(rng), x(rng), x(rng)}, {}};
    const auto pieces = bspline_grid_patches(5, 6, grid);
    ASSERT_EQ(pieces.size(), 2u * 3u);
    for (double s : {0.0, 0.25, 0.8}) {
        // Piece (row 0, col 0) ends at u = 1 where piece (0, 1) starts; rows likewise.
        expect_near(pieces[0].eval_matrix(1, s), pieces[1].eval_matrix(0, s), kEps, "across u");
        expect_near(pieces[0].eval_matrix(s, 1), pieces[3].eval_matrix(s, 0), kEps, "across v");
    }
}

TEST(QuadGrid, PatchesShareTheirBoundaryRows) {
    const PatchModel arch = test::arch_model();
    ASSERT_EQ(arch.patches.size(), 8u);
    const auto& a = std::get<QuadPatch>(arch.patches[0]);
    const auto& b = std::get<QuadPatch>(arch.patches[1]);
    EXPECT_EQ(a.column(2), b.column(0));
    // Texture coordinates ride along: (s, t) at a corner is the grid's.
    EXPECT_EQ(a.eval(1, 1).st, a.c[2][2].st);
}

TEST(PatchNormal, OutwardOnTheClosedSphereIncludingItsPoles) {
    const PatchModel sphere = test::sphere_model();
    for (const AnyPatch& any : sphere.patches) {
        const auto& p = std::get<CubicPatch>(any);
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j) {
                const double u = i / 8.0, v = j / 8.0;
                const Point3 x = p.eval(u, v).p;
                const Vec3 n = patch_normal(p, u, v);
                ASSERT_NEAR(n.length(), 1.0, 1e-12) << "u " << u << " v " << v;
                // The surface is within 0.03% of the unit sphere: n ~ x / |x|.
                EXPECT_GT(n.dot(x.to_vec().normalized()), 0.999) << "at " << x;
            }
    }
}

TEST(PatchNormal, PoleUsesTheLimitDirection) {
    const PatchModel sphere = test::sphere_model();
    const auto& lid = std::get<CubicPatch>(sphere.patches[0]);
    ASSERT_EQ(lid.c[3][0].p, lid.c[3][3].p); // the last row collapsed to the pole
    for (double u : {0.0, 0.4, 1.0}) {
        const auto d = lid.derivatives(u, 1);
        EXPECT_EQ(d.du.length(), 0.0);
        const Vec3 pole = patch_normal(lid, u, 1);
        EXPECT_NEAR(pole.z, 1.0, 1e-12) << "u " << u;
        // The limit agrees with the normal just below the pole.
        EXPECT_GT(pole.dot(patch_normal(lid, u, 1 - 1e-7)), 1 - 1e-6);
    }
    const auto& south = std::get<CubicPatch>(sphere.patches[4]);
    EXPECT_NEAR(patch_normal(south, 0.5, 1).z, -1.0, 1e-12);
}

TEST(PatchNormal, PatchCollapsedToAPointHasNone) {
    CubicPatch p;
    for (auto& row : p.c) row.fill({{1, 2, 3}, {}});
    EXPECT_EQ(patch_normal(p, 0.5, 0.5), Vec3{});
}

} // namespace
} // namespace casteljau
