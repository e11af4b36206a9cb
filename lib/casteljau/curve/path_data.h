// Parser for SVG path data (SVG 1.1 Second Edition, section 8.3.9, the BNF).
//
// The whole grammar: moveto/lineto/horizontal/vertical/curveto/smooth curveto/
// quadratic/smooth quadratic/elliptical arc/closepath, absolute (upper case)
// and relative (lower case), implicit repetition of a command's arguments
// (and a moveto's extra pairs as linetos), numbers in the compact forms the
// grammar allows ("M1.5.5" is 1.5 then .5; "1e-3"; "-1-2" is two numbers) and
// arc flags written without separators ("a1 1 0 00 1 1").
//
// Error handling follows SVG 1.1 F.2: the path is rendered up to the last
// complete command before the error, so the result carries both the path
// built so far and the first error with its character offset. A number that
// overflows a double is an error, never an infinity in the path.
#pragma once

#include "casteljau/curve/path.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace casteljau {

/// Where SVG path data went wrong, and what was wrong.
struct PathDataError {
    std::size_t offset = 0; ///< byte offset into the path data
    std::string message;
};

/// Parsed path data: the path up to any error, and the error.
struct PathDataResult {
    Path path;                          ///< everything before the error
    std::optional<PathDataError> error; ///< empty when the whole string parsed
};

PathDataResult parse_path_data(std::string_view data);

} // namespace casteljau
