// The mesh renderer: the z-buffer keeps the nearest surface whatever the
// order, coverage is the sampled area (antialiased edges), triangles through
// the near plane are clipped, and cameras frame what they look at.
#include "casteljau/render3d/camera.h"
#include "casteljau/render3d/mesh_raster.h"
#include "patch_models.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

// Camera at the origin looking down +z, 100 px per unit at depth 1.
ScreenProjection straight_view(int w, int h) {
    ScreenProjection v;
    v.focal = 100;
    v.center = {w / 2.0, h / 2.0};
    v.width = w;
    v.height = h;
    v.near = 0.01;
    return v;
}

// A quad at depth z covering pixels [x0, x1] x [y0, y1] of straight_view, one (s, t) throughout.
void add_quad(Mesh& m, const ScreenProjection& v, double x0, double y0, double x1, double y1,
              double z, Point st) {
    const auto at = [&](double x, double y) {
        return Point3{(x - v.center.x) / v.focal * z, (y - v.center.y) / v.focal * z, z};
    };
    const std::uint32_t base = std::uint32_t(m.positions.size());
    for (const Point3& p : {at(x0, y0), at(x1, y0), at(x1, y1), at(x0, y1)}) {
        m.positions.push_back(p);
        m.normals.push_back({0, 0, -1});
        m.st.push_back(st);
    }
    m.triangles.push_back({base, base + 1, base + 2});
    m.triangles.push_back({base, base + 2, base + 3});
}

TEST(MeshRenderer, NearestSurfaceWinsWhateverTheOrder) {
    const ScreenProjection v = straight_view(40, 40);
    // Checker cells: (s, t) = (0.01, 0.01) is light, (0.13, 0.01) dark.
    const Point light{0.01, 0.01}, dark{0.13, 0.01};
    const Texture checker;
    for (bool near_first : {true, false}) {
        Mesh m;
        if (near_first) add_quad(m, v, 10, 10, 30, 30, 2, light);
        add_quad(m, v, 0, 0, 40, 40, 5, dark);
        if (!near_first) add_quad(m, v, 10, 10, 30, 30, 2, light);
        Canvas c(40, 40);
        MeshRenderer().render(m, v, {&checker, {}, false}, c);
        const Premul centre = c.row(20)[20], outside = c.row(2)[2];
        EXPECT_GT(centre.r, outside.r + 0.2f) << "near first " << near_first;
        EXPECT_FLOAT_EQ(centre.a, 1.0f);
    }
}

TEST(MeshRenderer, EdgesAreCoveredByTheirArea) {
    const ScreenProjection v = straight_view(32, 32);
    Mesh m;
    add_quad(m, v, 4.5, 4.25, 20.5, 27.75, 3, {});
    Canvas c(32, 32);
    MeshRenderer().render(m, v, {}, c);
    EXPECT_FLOAT_EQ(c.row(10)[4].a, 0.5f);  // half the pixel's samples
    EXPECT_FLOAT_EQ(c.row(4)[10].a, 0.75f); // three rows of four
    EXPECT_FLOAT_EQ(c.row(10)[10].a, 1.0f);
    EXPECT_FLOAT_EQ(c.row(10)[21].a, 0.0f);
    double sum = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) sum += c.row(y)[x].a;
    EXPECT_NEAR(sum, 16.0 * 23.5, 1e-3);
}

TEST(MeshRenderer, TrianglesThroughTheNearPlaneAreClipped) {
    const ScreenProjection v = straight_view(32, 32);
    Mesh m;
    m.positions = {{-1, 0.2, -1}, {1, 0.2, -1}, {0, 0.2, 4}};
    m.normals.assign(3, {0, -1, 0});
    m.st.assign(3, {});
    m.triangles = {{0, 1, 2}};
    Canvas c(32, 32);
    MeshRenderer().render(m, v, {}, c);
    double sum = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) sum += c.row(y)[x].a;
    EXPECT_GT(sum, 10); // the part in front is drawn, nothing blows up
}

TEST(Camera, OrbitViewFramesTheModel) {
    const PatchModel sphere = test::sphere_model();
    for (double az : {0.0, 90.0, 200.0})
        for (double el : {-60.0, 0.0, 45.0, 90.0}) {
            const ScreenProjection v =
                make_projection(orbit_view(sphere.control_bounds(), az, el, 300, 200), 300, 200);
            for (const AnyPatch& any : sphere.patches)
                for (const auto& row : std::get<CubicPatch>(any).c)
                    for (const PatchPoint& q : row) {
                        const Point p = v.project(q.p);
                        EXPECT_GE(p.x, 0);
                        EXPECT_LE(p.x, 300);
                        EXPECT_GE(p.y, 0);
                        EXPECT_LE(p.y, 200);
                    }
            // The model is large in the frame: the sphere (radius 1, in a box whose
            // bounding sphere has radius sqrt 3) spans over half the height.
            const double span =
                distance(v.project(Point3{} - v.right), v.project(Point3{} + v.right));
            EXPECT_GT(span, 100) << "az " << az << " el " << el;
        }
}

} // namespace
} // namespace casteljau
