// fill_run's two forms against the plain loop: runs of every length from 0
// to 150 pixels at every 4-byte offset within 64 bytes, so that every
// alignment of the vector stores and of their overlapping ends is met.
#include "casteljau/paint/cpu.h"
#include "casteljau/paint/fill_run.h"

#include <cstdlib>
#include <gtest/gtest.h>
#include <vector>

namespace casteljau {
namespace {

using Fill = void (*)(Premul8*, int, Premul8) noexcept;

// Runs `fill` over every run and checks that exactly the run's pixels take
// the color: the pixels around it keep theirs.
void expect_exact_runs(Fill fill, const char* name) {
    const Premul8 old{1, 2, 3, 4}, color{200, 100, 50, 255};
    constexpr int kMargin = 40, kMaxLen = 150, kOffsets = 16;
    std::vector<Premul8> row(kMargin + kOffsets + kMaxLen + kMargin);
    for (int offset = 0; offset < kOffsets; ++offset)
        for (int len = 0; len <= kMaxLen; ++len) {
            std::fill(row.begin(), row.end(), old);
            const int x = kMargin + offset;
            fill(row.data() + x, len, color);
            for (int i = 0; i < int(row.size()); ++i)
                ASSERT_EQ(row[std::size_t(i)], i >= x && i < x + len ? color : old)
                    << name << ": run of " << len << " from offset " << offset << ", pixel "
                    << i - x;
        }
}

TEST(FillRun, Sse2FormWritesExactlyTheRun) { expect_exact_runs(detail::fill_run_sse2, "sse2"); }

TEST(FillRun, Avx2FormWritesExactlyTheRun) {
    if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2";
    expect_exact_runs(detail::fill_run_avx2, "avx2");
}

// The wider forms run where the CPU has them, unless CASTELJAU_NO_AVX2 asks
// for the baseline ones (scripts/test.sh runs the paint tests so too).
TEST(Cpu, WiderFormsRunWhereTheCpuHasThemAndTheEnvironmentAllows) {
    const char* v = std::getenv("CASTELJAU_NO_AVX2");
    const bool asked_baseline = v && *v;
    EXPECT_EQ(avx2_disabled_by_environment(), asked_baseline);
    EXPECT_EQ(use_avx2, cpu_has_avx2() && !asked_baseline);
}

TEST(FillRun, DispatchedFormWritesExactlyTheRun) { expect_exact_runs(fill_run, "dispatched"); }

} // namespace
} // namespace casteljau
