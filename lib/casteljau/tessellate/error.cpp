#include "casteljau/tessellate/error.h"

#include <algorithm>

namespace casteljau {

namespace {

constexpr int kOrder = 6;

bool seen(const ScreenProjection& view, const Vec3 (&c)[3]) {
    double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
    for (const Vec3& v : c) {
        if (v.z < view.near) return false;
        const Point p = view.to_pixels(v);
        lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
        lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
    }
    return hi_x >= 0 && lo_x <= view.width && hi_y >= 0 && lo_y <= view.height;
}

} // namespace

double measure_max_error_px(const PatchModel& model, const Mesh& mesh,
                            const ScreenProjection& view) {
    double worst = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const TriangleSource& src = mesh.sources[t];
        const Vec3 c[3] = {view.to_camera(mesh.positions[tri[0]]),
                           view.to_camera(mesh.positions[tri[1]]),
                           view.to_camera(mesh.positions[tri[2]])};
        if (!seen(view, c)) continue;
        std::visit(
            [&](const auto& patch) {
                for (int i = 0; i <= kOrder; ++i)
                    for (int j = 0; i + j <= kOrder; ++j) {
                        const double b0 = double(i) / kOrder, b1 = double(j) / kOrder,
                                     b2 = 1.0 - b0 - b1;
                        const Vec3 x = b0 * c[0] + b1 * c[1] + b2 * c[2];
                        const Point uv =
                            Point{} + (b0 * src.uv[0].to_vec() + b1 * src.uv[1].to_vec() +
                                       b2 * src.uv[2].to_vec());
                        const Vec3 s = view.to_camera(patch.eval(uv.x, uv.y).p);
                        if (s.z < view.near) continue;
                        worst = std::max(worst, distance(view.to_pixels(x), view.to_pixels(s)));
                    }
            },
            model.patches[src.patch]);
    }
    return worst;
}

} // namespace casteljau
