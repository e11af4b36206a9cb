#include "casteljau/tessellate/uniform.h"

#include "casteljau/tessellate/grid_vertices.h"

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

} // namespace casteljau
