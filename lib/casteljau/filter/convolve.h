// feConvolveMatrix (Filter Effects 1, "Filter primitive feConvolveMatrix",
// #feConvolveMatrixElement).
#pragma once

#include "casteljau/filter/filter_image.h"

#include <vector>

namespace casteljau {

/// The attributes of feConvolveMatrix, resolved by the caller: `kernel` holds
/// order_x * order_y values row by row as written in kernelMatrix, `divisor`
/// is non-zero (the caller substitutes the spec's default), 0 <= target_x <
/// order_x, 0 <= target_y < order_y. Parameters that break these make the
/// primitive a pass-through (the spec's rule for a wrong kernel size).
struct ConvolveMatrix {
    int order_x = 3, order_y = 3;
    std::vector<float> kernel;
    float divisor = 1, bias = 0;
    int target_x = 1, target_y = 1;
    EdgeMode edge = EdgeMode::Duplicate;
    bool preserve_alpha = false;
};

/// Whether `m` satisfies ConvolveMatrix's preconditions.
bool valid_kernel(const ConvolveMatrix& m) noexcept;

/// The convolution of `in` by `m` into `out` over `sub`, beyond the window's
/// edges as `m.edge` says. Precondition: `out` has `in`'s box and is
/// transparent black.
void convolve(const FilterImage& in, FilterImage& out, const Subregion& sub,
              const ConvolveMatrix& m) noexcept;

} // namespace casteljau
