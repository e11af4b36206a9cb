#include "casteljau/patch/patch_model.h"

namespace casteljau {

namespace {

template <int M, int N>
AnyPatch square(const BezierPatch<M, N>& p) {
    if constexpr (M < N)
        return square(elevate_u(p));
    else if constexpr (N < M)
        return square(elevate_v(p));
    else
        return AnyPatch{p};
}

template <int M, int N>
AnyPatch from_grid(std::span<const PatchPoint> points) {
    BezierPatch<M, N> p;
    for (int r = 0; r <= N; ++r)
        for (int k = 0; k <= M; ++k) p.c[r][k] = points[r * (M + 1) + k];
    return square(p);
}

} // namespace

AnyPatch bezier_from_grid(int du, int dv, std::span<const PatchPoint> points) {
    using Make = AnyPatch (*)(std::span<const PatchPoint>);
    static constexpr Make table[3][3] = {
        {from_grid<1, 1>, from_grid<1, 2>, from_grid<1, 3>},
        {from_grid<2, 1>, from_grid<2, 2>, from_grid<2, 3>},
        {from_grid<3, 1>, from_grid<3, 2>, from_grid<3, 3>},
    };
    return table[du - 1][dv - 1](points);
}

} // namespace casteljau
