// The sweep: running sums of a CoverageRow turned into coverage by the fill
// rule, emitted as spans.
//
// With s the accumulated signed coverage of a pixel (the winding number
// integrated over the pixel), coverage is
//   nonzero:  min(|s|, 1)
//   even-odd: |s| folded into [0, 1] with period 2 (1 - |(|s| mod 2) - 1|)
// the rules of FreeType's smooth rasterizer. Both are exact for pixels where
// the winding number takes one value besides 0; where several nonzero values
// meet inside one pixel they are the usual area approximation.
#pragma once

#include "casteljau/raster/accumulate.h"
#include "casteljau/raster/span.h"

#include <vector>

namespace casteljau {

enum class FillRule { NonZero, EvenOdd };

/// Coverage below this is invisible in any 8-bit or half-float output; runs
/// of it (the inside of holes, where float sums cancel to ~1e-7) are not
/// emitted as spans.
inline constexpr float kInvisible = 1e-6f;

inline float apply_fill_rule(float s, FillRule rule) {
    const float a = s < 0 ? -s : s;
    if (rule == FillRule::NonZero) return a < 1.0f ? a : 1.0f;
    const float m = a - 2.0f * float(int(a * 0.5f));
    return m > 1.0f ? 2.0f - m : m;
}

/// Sweeps row `y`, emits spans of the covered pixels (a per-pixel span may
/// hold pixels of coverage 0 between covered ones), and leaves the row zeroed.
/// A running sum still nonzero after the last touched column (an outline that
/// extends past the right border) covers the rest of the row.
/// `scratch` holds the coverage values and is grown as needed.
/// Row column i is pixel x_offset + i.
void sweep_row(CoverageRow& row, int y, int x_offset, FillRule rule, std::vector<float>& scratch,
               SpanSink& sink);

} // namespace casteljau
