#include "casteljau/raster/sweep.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

namespace {
// Coverage below this is invisible in any 8-bit or half-float output; runs of
// it (the inside of holes, where float sums cancel to ~1e-7) are not emitted.
constexpr float kInvisible = 1e-6f;
} // namespace

void sweep_row(CoverageRow& row, int y, int x_offset, FillRule rule, std::vector<float>& scratch,
               SpanSink& sink) {
    const int begin = row.begin();
    int end = std::min(row.end(), row.width());
    if (begin >= end) {
        if (row.begin() < row.end())
            std::fill(row.data() + row.begin(), row.data() + row.end(), 0.0f);
        row.clear_range();
        return;
    }
    if (scratch.size() < std::size_t(row.width())) scratch.resize(std::size_t(row.width()));
    float* acc = row.data();
    float* cov = scratch.data();
    // The running sum changes only where an edge deposited something; between
    // those columns the coverage is constant, so runs of zeros are filled.
    float s = 0;
    for (int i = begin; i < end;) {
        s += acc[i];
        acc[i] = 0;
        const float c = apply_fill_rule(s, rule);
        cov[i++] = c;
        int j = i;
        // Four columns per test: one branch per four, not one per column.
        while (j + 4 <= end && ((acc[j] == 0.0f) & (acc[j + 1] == 0.0f) & (acc[j + 2] == 0.0f) &
                                (acc[j + 3] == 0.0f)))
            j += 4;
        while (j < end && acc[j] == 0.0f) ++j;
        std::fill(cov + i, cov + j, c);
        i = j;
    }
    std::fill(acc + end, acc + row.end(), 0.0f);
    row.clear_range();
    // Past the last touched column only edges clamped onto the right border
    // remain (they are vertical there), so the winding is a whole number; the
    // sum carries float residue (~1e-7 per edge), which must not paint the
    // rest of the row faintly. Rounded, it is the winding of the rest.
    const float rest = apply_fill_rule(std::nearbyint(s), rule);
    if (rest > 0.0f) {
        std::fill(cov + end, cov + row.width(), rest);
        end = row.width();
    }
    int i = begin;
    while (i < end) {
        while (i < end && cov[i] < kInvisible) ++i;
        const int start = i;
        while (i < end && cov[i] >= kInvisible) ++i;
        if (i > start) sink.span({y, x_offset + start, i - start, cov + start});
    }
}

} // namespace casteljau
