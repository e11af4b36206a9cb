#include "casteljau/raster/sweep.h"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace casteljau {

namespace {

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

#if defined(__SSE2__)
// apply_fill_rule on the low lane, with the same bits and without a branch:
// a select by mask where the scalar form's comparisons compiled to jumps
// that mispredicted wherever coverage alternated between partial and full.
template <FillRule Rule>
__m128 fill_rule_ss(__m128 s) {
    const __m128 one = _mm_set_ss(1.0f);
    const __m128 a = _mm_andnot_ps(_mm_set_ss(-0.0f), s); // |s|
    if constexpr (Rule == FillRule::NonZero) {
        return _mm_min_ss(a, one);
    } else {
        const __m128 whole = _mm_cvtepi32_ps(_mm_cvttps_epi32(_mm_mul_ss(a, _mm_set_ss(0.5f))));
        const __m128 m = _mm_sub_ss(a, _mm_mul_ss(_mm_set_ss(2.0f), whole));
        const __m128 over = _mm_cmpgt_ss(m, one); // m > 1: 2 - m
        return _mm_or_ps(_mm_and_ps(over, _mm_sub_ss(_mm_set_ss(2.0f), m)), _mm_andnot_ps(over, m));
    }
}
#endif

// Turns one row's runs of constant coverage, left to right, into spans.
class RowSpans {
  public:
    RowSpans(SpanSink& sink, float* cov, int y, int x_offset)
        : sink_(sink), cov_(cov), y_(y), x_offset_(x_offset) {}

    // Columns [i, j) have coverage c; i is the end of the previous run.
    // Inlined by force: with the sweep a template on the fill rule, GCC
    // left this a call per run (1% of the tiger's samples, and the 2k blobs'
    // frame 4% slower).
    [[gnu::always_inline]] void run(int i, int j, float c) {
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
    template <FillRule Rule>
    void sum(float* acc, int i, int j, float& s) {
        int first = j, last = i; // the visible columns lie in [first, last)
#if defined(__SSE2__)
        __m128 sum = _mm_set_ss(s);
        const __m128 invisible = _mm_set_ss(kInvisible);
        for (; i < j; ++i) {
            sum = _mm_add_ss(sum, _mm_load_ss(acc + i));
            acc[i] = 0;
            const __m128 c = fill_rule_ss<Rule>(sum);
            const __m128 visible = _mm_cmpge_ss(c, invisible);
            _mm_store_ss(cov_ + i, _mm_and_ps(c, visible));
            const bool v = _mm_movemask_ps(visible) & 1;
            first = std::min(first, v ? i : j);
            last = v ? i + 1 : last;
        }
        s = _mm_cvtss_f32(sum);
#else
        for (; i < j; ++i) {
            s += acc[i];
            acc[i] = 0;
            const float c = apply_fill_rule(s, Rule);
            const bool v = c >= kInvisible;
            cov_[i] = v ? c : 0.0f;
            first = std::min(first, v ? i : j);
            last = v ? i + 1 : last;
        }
#endif
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
template <FillRule Rule>
float sweep_sparse(const CoverageRow& row, float* acc, int begin, int end, RowSpans& spans) {
    float s = 0;
    for (int i = begin; i < end;) {
        // The cluster is [i, last], and its last column that changes the sum
        // opens the constant run: an edge on a column border deposits an
        // exact 0 in the column after it (accumulate.h), and the full rows of
        // a rectangle would otherwise start with a one-pixel span.
        const int after = row.next_unmarked(i + 1, end);
        int last = after - 1;
        while (last > i && acc[last] == 0.0f) --last;
        spans.sum<Rule>(acc, i, last, s);
        s += acc[last];
        acc[last] = 0;
        const int next = row.next_marked(after, end);
        spans.run(last, next, apply_fill_rule(s, Rule));
        i = next;
    }
    return s;
}

// The same for a range narrower than kSolidRun (a thin stroke's row), where
// no run can be solid: every column in one plain pass, which costs less than
// finding the touched ones. The pixels are those of the sparse walk (an
// untouched column adds an exact 0 to the sum).
template <FillRule Rule>
float sweep_dense(float* acc, int begin, int end, RowSpans& spans) {
    float s = 0;
    spans.sum<Rule>(acc, begin, end, s);
    return s;
}

template <FillRule Rule>
void sweep(CoverageRow& row, int y, int x_offset, std::vector<float>& scratch, SpanSink& sink) {
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
    const float s = end - begin < kSolidRun ? sweep_dense<Rule>(acc, begin, end, spans)
                                            : sweep_sparse<Rule>(row, acc, begin, end, spans);
    if (end < row.end()) std::fill(acc + end, acc + row.end(), 0.0f); // not a memset call per row
    row.clear_range();
    // Past the last touched column only edges clamped onto the right border
    // remain (they are vertical there), so the winding is a whole number; the
    // sum carries float residue (~1e-7 per edge), which must not paint the
    // rest of the row faintly. Rounded, it is the winding of the rest.
    if (end < row.width()) spans.run(end, row.width(), apply_fill_rule(nearest_winding(s), Rule));
    spans.flush();
}

} // namespace

void sweep_row(CoverageRow& row, int y, int x_offset, FillRule rule, std::vector<float>& scratch,
               SpanSink& sink) {
    if (rule == FillRule::NonZero)
        sweep<FillRule::NonZero>(row, y, x_offset, scratch, sink);
    else
        sweep<FillRule::EvenOdd>(row, y, x_offset, scratch, sink);
}

} // namespace casteljau
