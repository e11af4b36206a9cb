// The SVG `transform` attribute (SVG 1.1, 7.6): a list of matrix(a b c d e f),
// translate(x [y]), scale(sx [sy]), rotate(deg [cx cy]), skewX(deg), skewY(deg),
// separated by whitespace and/or commas, applied left to right as nested
// coordinate systems (so the product is taken in list order).
#pragma once

#include "casteljau/geom/affine.h"

#include <optional>
#include <string>
#include <string_view>

namespace casteljau {

/// The transform, or an error message naming the offending function.
struct TransformResult {
    Affine transform;
    std::string error; ///< empty on success
};

TransformResult parse_transform_list(std::string_view text);

} // namespace casteljau
