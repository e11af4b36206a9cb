#include "patch_models.h"

#include "casteljau/patch/grid.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace casteljau::test {

namespace {

// The cubic quarter circle's inner control point (4/3)(sqrt 2 - 1).
const double kArc = 4.0 / 3.0 * (std::sqrt(2.0) - 1.0);

} // namespace

PatchModel sphere_model() {
    // Profile from the equator (rho 1, z 0) to the pole (rho 0, z 1).
    const double rho[4] = {1, 1, kArc, 0}, height[4] = {0, kArc, 1, 1};
    const Vec2 quarter[4] = {{1, 0}, {1, kArc}, {kArc, 1}, {0, 1}};
    PatchModel model;
    for (double side : {1.0, -1.0})
        for (int q = 0; q < 4; ++q) {
            CubicPatch p;
            for (int r = 0; r < 4; ++r)
                for (int k = 0; k < 4; ++k) {
                    // The lower half runs the circle backwards, so that du x dv
                    // still points outward after the mirror in z.
                    Vec2 c = quarter[side > 0 ? k : 3 - k];
                    for (int turn = 0; turn < q; ++turn) c = c.perp(); // exact
                    const double z = side * height[r];
                    p.c[r][k] = {{rho[r] * c.x, rho[r] * c.y, z},
                                 {(q + double(k) / 3) / 4, side * double(r) / 3}};
                }
            model.patches.push_back(p);
        }
    return model;
}

PatchModel arch_model() {
    const int rows = 5, cols = 9;
    std::vector<PatchPoint> grid;
    for (int r = 0; r < rows; ++r)
        for (int k = 0; k < cols; ++k) {
            // Columns go over the arch in quarter turns; even columns are on
            // the circle, odd ones at the corners of the circumscribed square,
            // which makes each biquadratic piece an exact-looking quarter arc.
            const double a = std::numbers::pi * (k / 2) / 4 + (k % 2) * std::numbers::pi / 8;
            const double radius = 128 * (k % 2 ? 1 / std::cos(std::numbers::pi / 8) : 1.0);
            grid.push_back(
                {{radius * std::cos(a), 48.0 * r, radius * std::sin(a)}, {k / 8.0 * 4, r / 4.0}});
        }
    PatchModel model;
    for (const QuadPatch& p : quad_grid_patches(rows, cols, grid)) model.patches.push_back(p);
    return model;
}

PatchModel bump_model() {
    const int n = 8;
    std::vector<PatchPoint> grid;
    for (int r = 0; r < n; ++r)
        for (int k = 0; k < n; ++k) {
            const double z = (r == 4 && k == 4) ? 400 : 0;
            grid.push_back({{100.0 * k, 100.0 * r, z}, {k / 7.0, r / 7.0}});
        }
    PatchModel model;
    for (const BSplinePatch& b : bspline_grid_patches(n, n, grid))
        model.patches.push_back(b.to_bezier());
    return model;
}

Topology mesh_topology(const Mesh& mesh) {
    std::map<std::array<double, 3>, std::size_t> ids;
    std::vector<Point3> points;
    std::vector<std::size_t> welded(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const Point3 p = mesh.positions[i];
        const auto [it, fresh] = ids.try_emplace({p.x + 0.0, p.y + 0.0, p.z + 0.0}, points.size());
        if (fresh) points.push_back(p);
        welded[i] = it->second;
    }
    std::map<std::pair<std::size_t, std::size_t>, int> uses;
    for (const auto& t : mesh.triangles) {
        const std::size_t a = welded[t[0]], b = welded[t[1]], c = welded[t[2]];
        if (a == b || b == c || c == a) continue;
        for (auto [p, q] : {std::pair{a, b}, {b, c}, {c, a}})
            ++uses[{std::min(p, q), std::max(p, q)}];
    }
    Topology topo;
    topo.edges = uses.size();
    for (const auto& [edge, n] : uses) {
        if (n > 2) ++topo.overused_edges;
        if (n != 1) continue;
        ++topo.boundary_edges;
        const Point3 a = points[edge.first], b = points[edge.second];
        const Vec3 ab = b - a;
        for (const Point3& p : points) {
            const double t = (p - a).dot(ab) / ab.length_sq();
            if (t <= 1e-9 || t >= 1 - 1e-9) continue;
            if ((p - lerp(a, b, t)).length() <= 1e-9 * ab.length()) ++topo.t_junctions;
        }
    }
    return topo;
}

} // namespace casteljau::test
