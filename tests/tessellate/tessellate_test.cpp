// Tessellation: vertices lie on the surface, the measured projected error is
// within the tolerance, adaptive meshes are watertight (within and across
// patches), uniform grids have the promised shape and winding, and adaptive
// beats uniform at equal measured error where the curvature is uneven.
#include "casteljau/patch/normal.h"
#include "casteljau/render3d/camera.h"
#include "casteljau/tessellate/adaptive.h"
#include "casteljau/tessellate/error.h"
#include "casteljau/tessellate/uniform.h"
#include "patch_models.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

struct Case {
    const char* name;
    PatchModel (*model)();
    double azimuth, elevation;
};

const Case kCases[] = {
    {"sphere", test::sphere_model, 30, 20},
    {"sphere_from_above", test::sphere_model, 0, 89.99},
    {"arch", test::arch_model, -60, 25},
    {"bump", test::bump_model, 10, 35},
};

ScreenProjection view_of(const PatchModel& m, const Case& c, int w = 640, int h = 480) {
    return make_projection(orbit_view(m.control_bounds(), c.azimuth, c.elevation, w, h), w, h);
}

// The largest distance from a mesh vertex to the surface at its (u, v).
double vertex_offset(const PatchModel& model, const Mesh& mesh) {
    double worst = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const Point uv = mesh.sources[t].uv[k];
            const Point3 s = std::visit([&](const auto& p) { return p.eval(uv.x, uv.y).p; },
                                        model.patches[mesh.sources[t].patch]);
            worst = std::max(worst, distance(s, mesh.positions[mesh.triangles[t][k]]));
        }
    return worst;
}

TEST(AdaptiveTessellation, MeasuredErrorWithinToleranceAndVerticesOnTheSurface) {
    for (const Case& c : kCases) {
        const PatchModel model = c.model();
        const ScreenProjection view = view_of(model, c);
        const double scale = model.control_bounds().diagonal();
        for (double tol : {1.0, 0.25, 0.1}) {
            Mesh mesh;
            tessellate_adaptive(model, view, tol, mesh);
            ASSERT_FALSE(mesh.triangles.empty());
            const double err = measure_max_error_px(model, mesh, view);
            EXPECT_LE(err, tol) << c.name << " tol " << tol;
            // The bound is not wildly loose either: the error is a fair share of it.
            EXPECT_GT(err, 0.1 * tol) << c.name << " tol " << tol;
            EXPECT_LE(vertex_offset(model, mesh), 1e-12 * scale) << c.name;
        }
    }
}

TEST(AdaptiveTessellation, ClosedSphereIsWatertightAcrossPatchesAndPoles) {
    const PatchModel sphere = test::sphere_model();
    for (const Case& c : kCases) {
        if (c.model != test::sphere_model) continue;
        for (double tol : {1.0, 0.25}) {
            Mesh mesh;
            tessellate_adaptive(sphere, view_of(sphere, c), tol, mesh);
            const test::Topology topo = test::mesh_topology(mesh);
            EXPECT_EQ(topo.boundary_edges, 0u) << c.name << " tol " << tol;
            EXPECT_EQ(topo.overused_edges, 0u) << c.name << " tol " << tol;
            EXPECT_GT(topo.edges, 100u);
        }
    }
}

// fuzz_patch_render found a B-spline grid reaching through the camera, which
// projects to unbounded size: refined to the depth cap, it took minutes. The
// piece budget stops it, and what it leaves is still watertight.
TEST(AdaptiveTessellation, PieceBudgetBoundsTheWorkAndKeepsTheMeshWatertight) {
    const PatchModel sphere = test::sphere_model();
    const ScreenProjection view = view_of(sphere, kCases[0]);
    Mesh full;
    const AdaptiveStats unlimited = tessellate_adaptive(sphere, view, 0.1, full);
    EXPECT_FALSE(unlimited.budget_reached);
    ASSERT_GT(unlimited.pieces, 200u);
    for (const std::size_t budget : {std::size_t(1), std::size_t(37), unlimited.pieces / 3}) {
        Mesh mesh;
        const AdaptiveStats st = tessellate_adaptive(sphere, view, 0.1, budget, mesh);
        EXPECT_TRUE(st.budget_reached) << budget;
        // Each patch keeps at least one piece; a split in flight adds one more.
        EXPECT_LE(st.pieces, budget + 2 * sphere.patches.size()) << budget;
        EXPECT_LT(mesh.triangles.size(), full.triangles.size()) << budget;
        const test::Topology topo = test::mesh_topology(mesh);
        EXPECT_EQ(topo.boundary_edges, 0u) << budget;
        EXPECT_EQ(topo.overused_edges, 0u) << budget;
    }
    EXPECT_EQ(default_piece_budget(view),
              std::min(kMaxPieces, 16 * std::size_t(view.width) * std::size_t(view.height)));
}

TEST(AdaptiveTessellation, OpenModelsHaveNoTJunctions) {
    for (const Case& c : kCases) {
        const PatchModel model = c.model();
        Mesh mesh;
        tessellate_adaptive(model, view_of(model, c), 0.25, mesh);
        const test::Topology topo = test::mesh_topology(mesh);
        EXPECT_EQ(topo.t_junctions, 0u) << c.name;
        EXPECT_EQ(topo.overused_edges, 0u) << c.name;
    }
}

TEST(AdaptiveTessellation, TrianglesFaceAlongTheSurfaceNormal) {
    const PatchModel sphere = test::sphere_model();
    Mesh mesh;
    tessellate_adaptive(sphere, view_of(sphere, kCases[0]), 0.25, mesh);
    for (const auto& t : mesh.triangles) {
        const Point3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        const Vec3 n = (b - a).cross(c - a);
        const Vec3 centroid = (a.to_vec() + b.to_vec() + c.to_vec()) / 3;
        EXPECT_GT(n.dot(centroid), 0) << "a triangle faces inward";
    }
}

TEST(UniformTessellation, GridShapeWindingAndWatertightness) {
    const PatchModel sphere = test::sphere_model();
    Mesh mesh;
    tessellate_uniform(sphere, 7, 5, mesh);
    // Two triangles a cell, less the ones that collapse at the poles (one per
    // cell in the row next to each pole).
    EXPECT_EQ(mesh.triangles.size(), 8u * (2 * 7 * 5 - 7));
    for (const auto& t : mesh.triangles) {
        const Point3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        const Vec3 n = (b - a).cross(c - a);
        EXPECT_GT(n.dot(mesh.normals[t[0]] + mesh.normals[t[1]] + mesh.normals[t[2]]), 0);
    }
    const test::Topology topo = test::mesh_topology(mesh);
    EXPECT_EQ(topo.boundary_edges, 0u);
    EXPECT_EQ(topo.overused_edges, 0u);
    EXPECT_LE(vertex_offset(sphere, mesh), 1e-12 * 2);
}

TEST(AdaptiveTessellation, FewerTrianglesThanUniformAtEqualMeasuredError) {
    const PatchModel bump = test::bump_model();
    const ScreenProjection view = view_of(bump, kCases[3]);
    Mesh adaptive, uniform;
    tessellate_adaptive(bump, view, 0.25, adaptive);
    const double err = measure_max_error_px(bump, adaptive, view);
    const int steps = fewest_uniform_steps(bump, view, err, 1024, uniform);
    // The search's own promise: `steps` meets the error and one step fewer does not.
    tessellate_uniform(bump, steps - 1, steps - 1, uniform);
    EXPECT_GT(measure_max_error_px(bump, uniform, view), err);
    tessellate_uniform(bump, steps, steps, uniform);
    EXPECT_LE(measure_max_error_px(bump, uniform, view), err);
    EXPECT_LT(2 * adaptive.triangles.size(), uniform.triangles.size())
        << "adaptive " << adaptive.triangles.size() << " uniform " << uniform.triangles.size()
        << " at " << steps << " steps";
}

} // namespace
} // namespace casteljau
