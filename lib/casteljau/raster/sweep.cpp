#include "casteljau/raster/sweep.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

namespace {

// Coverage below this is invisible in any 8-bit or half-float output; runs of
// it (the inside of holes, where float sums cancel to ~1e-7) are not emitted.
constexpr float kInvisible = 1e-6f;

// A run of constant coverage at least this long leaves as a span of its own
// with one coverage value; shorter runs join the per-pixel span around them,
// where writing a few coverage values costs less than an extra span call.
constexpr int kSolidRun = 16;

// The nearest integer to a winding sum that is one up to float residue (no
// ties): inline, where std::nearbyint is a libm call on every row (x86-64
// has no rounding instruction before SSE4.1). Clamped to +-2^24, past which
// float holds no odd integer (so no winding is told apart there), to keep
// the conversion to int defined.
float nearest_winding(float s) {
    const float w = std::clamp(s, -0x1p24f, 0x1p24f);
    return float(int(w + std::copysign(0.5f, w)));
}

// Turns one row's runs of constant coverage, left to right, into spans.
class RowSpans {
  public:
    RowSpans(SpanSink& sink, float* cov, int y, int x_offset)
        : sink_(sink), cov_(cov), y_(y), x_offset_(x_offset) {}

    // Columns [i, j) have coverage c; i is the end of the previous run.
    void run(int i, int j, float c) {
        if (c < kInvisible) {
            flush();
        } else if (j - i >= kSolidRun) {
            flush();
            sink_.span({y_, x_offset_ + i, j - i, nullptr, c});
        } else {
            if (start_ < 0) start_ = i;
            std::fill(cov_ + i, cov_ + j, c);
            end_ = j;
        }
    }

    // Sums columns [i, j) of `acc` onto the running sum s, zeroing them, in
    // one plain pass without a branch per column; the visible columns join
    // the per-pixel span, in which invisible columns between them carry
    // coverage 0: compositing 0 leaves a pixel's bits as they are
    // (D' = 0 S + 1 D).
    void sum(float* acc, int i, int j, FillRule rule, float& s) {
        int first = j, last = i; // the visible columns lie in [first, last)
        for (; i < j; ++i) {
            s += acc[i];
            acc[i] = 0;
            const float c = apply_fill_rule(s, rule);
            const bool visible = c >= kInvisible;
            cov_[i] = visible ? c : 0.0f;
            first = visible && first == j ? i : first;
            last = visible ? i + 1 : last;
        }
        if (first < last) {
            if (start_ < 0) start_ = first;
            end_ = last;
        }
    }

    // Emits the per-pixel span in progress, if any.
    void flush() {
        if (start_ >= 0) sink_.span({y_, x_offset_ + start_, end_ - start_, cov_ + start_, 0.0f});
        start_ = -1;
    }

  private:
    SpanSink& sink_;
    float* cov_;
    int y_, x_offset_;
    int start_ = -1, end_ = 0; // the per-pixel span in progress: columns [start_, end_)
};

// Sums columns [begin, end) of `acc` into runs, zeroing them; returns the sum.
// Only touched columns are visited (CoverageRow's marks), cluster by cluster:
// a cluster is a run of touched columns, and past its last column the sum
// stays what that column left it (nothing was deposited in between), so
// the cluster's last column opens the run of constant coverage up to the
// next cluster. The columns before it are summed in one plain pass, as
// sweep_dense does: branches cost per cluster, not per column, where the
// walk column by column mispredicted on most (a third of the sweep's
// samples sat on one such branch in the tiger's profile). The sums are the
// same running sum, in the same order, bit for bit.
float sweep_sparse(const CoverageRow& row, float* acc, int begin, int end, FillRule rule,
                   RowSpans& spans) {
    float s = 0;
    for (int i = begin; i < end;) {
        const int last = row.next_unmarked(i + 1, end) - 1; // the cluster is [i, last]
        spans.sum(acc, i, last, rule, s);
        s += acc[last];
        acc[last] = 0;
        const int next = row.next_marked(last + 1, end);
        spans.run(last, next, apply_fill_rule(s, rule));
        i = next;
    }
    return s;
}

// The same for a range narrower than kSolidRun (a thin stroke's row), where
// no run can be solid: every column in one plain pass, which costs less than
// finding the touched ones. The pixels are those of the sparse walk (an
// untouched column adds an exact 0 to the sum).
float sweep_dense(float* acc, int begin, int end, FillRule rule, RowSpans& spans) {
    float s = 0;
    spans.sum(acc, begin, end, rule, s);
    return s;
}

} // namespace

void sweep_row(CoverageRow& row, int y, int x_offset, FillRule rule, std::vector<float>& scratch,
               SpanSink& sink) {
    const int begin = row.begin();
    const int end = std::min(row.end(), row.width());
    if (begin >= end) {
        if (row.begin() < row.end())
            std::fill(row.data() + row.begin(), row.data() + row.end(), 0.0f);
        row.clear_range();
        return;
    }
    if (scratch.size() < std::size_t(row.width())) scratch.resize(std::size_t(row.width()));
    float* acc = row.data();
    RowSpans spans(sink, scratch.data(), y, x_offset);
    const float s = end - begin < kSolidRun ? sweep_dense(acc, begin, end, rule, spans)
                                            : sweep_sparse(row, acc, begin, end, rule, spans);
    if (end < row.end()) std::fill(acc + end, acc + row.end(), 0.0f); // not a memset call per row
    row.clear_range();
    // Past the last touched column only edges clamped onto the right border
    // remain (they are vertical there), so the winding is a whole number; the
    // sum carries float residue (~1e-7 per edge), which must not paint the
    // rest of the row faintly. Rounded, it is the winding of the rest.
    if (end < row.width()) spans.run(end, row.width(), apply_fill_rule(nearest_winding(s), rule));
    spans.flush();
}

} // namespace casteljau
