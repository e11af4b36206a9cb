#include "casteljau/patch/grid.h"

namespace casteljau {

std::vector<QuadPatch> quad_grid_patches(int rows, int cols, std::span<const PatchPoint> points) {
    std::vector<QuadPatch> out;
    for (int r0 = 0; r0 + 2 < rows; r0 += 2)
        for (int k0 = 0; k0 + 2 < cols; k0 += 2) {
            QuadPatch q;
            for (int r = 0; r < 3; ++r)
                for (int k = 0; k < 3; ++k) q.c[r][k] = points[(r0 + r) * cols + k0 + k];
            out.push_back(q);
        }
    return out;
}

std::vector<BSplinePatch> bspline_grid_patches(int rows, int cols,
                                               std::span<const PatchPoint> points) {
    std::vector<BSplinePatch> out;
    for (int r0 = 0; r0 + 3 < rows; ++r0)
        for (int k0 = 0; k0 + 3 < cols; ++k0) {
            BSplinePatch b;
            for (int r = 0; r < 4; ++r)
                for (int k = 0; k < 4; ++k) b.c[r][k] = points[(r0 + r) * cols + k0 + k];
            out.push_back(b);
        }
    return out;
}

} // namespace casteljau
