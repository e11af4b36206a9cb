#include "casteljau/tessellate/uniform.h"

#include "casteljau/tessellate/error.h"
#include "casteljau/tessellate/grid_vertices.h"

#include <algorithm>

namespace casteljau {

void tessellate_uniform(const PatchModel& model, int steps_u, int steps_v, Mesh& out) {
    out.clear();
    MeshAssembler assembler(out);
    const auto nu = std::uint32_t(steps_u), nv = std::uint32_t(steps_v);
    for (std::uint32_t index = 0; index < model.patches.size(); ++index) {
        std::visit(
            [&](const auto& patch) {
                GridVertices grid(assembler, patch, index);
                for (std::uint32_t j = 0; j < nv; ++j)
                    for (std::uint32_t i = 0; i < nu; ++i) {
                        const std::uint32_t a = grid.at(i, nu, j, nv),
                                            b = grid.at(i + 1, nu, j, nv),
                                            c = grid.at(i + 1, nu, j + 1, nv),
                                            d = grid.at(i, nu, j + 1, nv);
                        const Point ua{double(i) / nu, double(j) / nv},
                            ub{double(i + 1) / nu, double(j) / nv},
                            uc{double(i + 1) / nu, double(j + 1) / nv},
                            ud{double(i) / nu, double(j + 1) / nv};
                        assembler.triangle({a, b, c}, {index, {ua, ub, uc}});
                        assembler.triangle({a, c, d}, {index, {ua, uc, ud}});
                    }
            },
            model.patches[index]);
    }
}

int fewest_uniform_steps(const PatchModel& model, const ScreenProjection& view, double max_error_px,
                         int max_steps, Mesh& scratch) {
    const auto meets = [&](int n) {
        tessellate_uniform(model, n, n, scratch);
        return measure_max_error_px(model, scratch, view) <= max_error_px;
    };
    int hi = 1;
    while (hi < max_steps && !meets(hi)) hi = std::min(2 * hi, max_steps);
    int lo = hi / 2; // fails (or is 0)
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        (meets(mid) ? hi : lo) = mid;
    }
    return hi;
}

} // namespace casteljau
