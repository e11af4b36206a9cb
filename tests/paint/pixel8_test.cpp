// 8-bit pixels: each composite is the float result rounded once, to nearest.
#include "casteljau/paint/canvas.h"
#include "corpus.h"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace casteljau {
namespace {

float channel(const Premul8& p, int i) {
    return float(i == 0 ? p.r : i == 1 ? p.g : i == 2 ? p.b : p.a);
}
float channel(const Premul& p, int i) { return i == 0 ? p.r : i == 1 ? p.g : i == 2 ? p.b : p.a; }

Premul random_premul(testing::Rng& rng) {
    const float a = rng.uniform(0, 1) < 0.3 ? 1.0f : float(rng.uniform(0, 1));
    return {a * float(rng.uniform(0, 1)), a * float(rng.uniform(0, 1)),
            a * float(rng.uniform(0, 1)), a};
}

// Every byte value survives the trip to float and back.
TEST(Pixel8, EveryByteRoundTrips) {
    for (int v = 0; v < 256; ++v) {
        const auto b = std::uint8_t(v);
        const Premul8 p{b, b, b, b};
        EXPECT_EQ(quantize(to_premul(p)), p) << v;
    }
}

// quantize is the nearest byte: at most half a step from 255 v, and clamped.
TEST(Pixel8, QuantizeIsTheNearestByte) {
    testing::Rng rng(81);
    for (int trial = 0; trial < 20000; ++trial) {
        const Premul c = random_premul(rng);
        const Premul8 q = quantize(c);
        for (int i = 0; i < 4; ++i)
            ASSERT_LE(std::fabs(channel(q, i) - 255.0f * channel(c, i)), 0.5f + 1e-4f)
                << "trial " << trial << " channel " << i << " value " << channel(c, i);
    }
    EXPECT_EQ(quantize({-0.5f, 2.0f, 0.0f, 1.5f}), (Premul8{0, 255, 0, 255}));
}

// Source-over onto bytes is within half a step of the float formula applied
// to the same starting pixel: one rounding, to nearest (truncating would be
// up to a whole step off, and biased).
TEST(Pixel8, BlendIsTheFloatBlendRoundedOnce) {
    testing::Rng rng(82);
    double signed_sum = 0;
    long n = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const Premul8 start = quantize(random_premul(rng));
        const Premul s = random_premul(rng);
        const float k = rng.uniform(0, 1) < 0.2 ? 1.0f : float(rng.uniform(0, 1));
        Premul exact = to_premul(start);
        blend_over(exact, s, k);
        Premul8 d = start;
        blend_over(d, s, k);
        for (int i = 0; i < 4; ++i) {
            const float err = channel(d, i) - 255.0f * channel(exact, i);
            ASSERT_LE(std::fabs(err), 0.5f + 1e-3f)
                << "trial " << trial << " channel " << i << " k " << k << " start "
                << channel(start, i) << " source " << channel(s, i);
            signed_sum += err, ++n;
        }
    }
    EXPECT_LT(std::fabs(signed_sum / double(n)), 0.02) << "rounding is biased";
}

// Coverage 0 leaves the bytes; full coverage of an opaque color stores it.
TEST(Pixel8, CoverageZeroKeepsAndOpaqueFullCoverageReplaces) {
    testing::Rng rng(83);
    for (int trial = 0; trial < 2000; ++trial) {
        const Premul8 start = quantize(random_premul(rng));
        Premul s = random_premul(rng);
        Premul8 d = start;
        blend_over(d, s, 0.0f);
        ASSERT_EQ(d, start) << "trial " << trial;
        s = premultiply({s.r, s.g, s.b, 1.0f});
        blend_over(d, s, 1.0f);
        ASSERT_EQ(d, quantize(s)) << "trial " << trial;
    }
}

// Fast against reference: a run blended four or eight pixels at a time
// carries the bits of blend_over pixel by pixel, per-pixel and constant
// coverage alike, whatever the run's length (the eight- and four-pixel
// bodies and the one-pixel tail), with coverage 0 and 1 and opaque sources
// among the cases: the SSE2 form, the AVX2 form (where the CPU has it) and
// the one blend_span_over chooses.
using PerPixelRun = void (*)(Premul8*, int, const Premul&, const float*);
using ConstantRun = void (*)(Premul8*, int, const Premul&, float);

void expect_runs_blend_as_pixel_by_pixel(PerPixelRun per_pixel, ConstantRun constant,
                                         const char* name) {
    testing::Rng rng(84);
    for (int trial = 0; trial < 3000; ++trial) {
        const int n = rng.integer(0, 40);
        std::vector<Premul8> start(std::size_t(n) + 1);
        std::vector<float> k(std::size_t(n) + 1);
        for (int i = 0; i < n; ++i) {
            start[std::size_t(i)] = quantize(random_premul(rng));
            const double pick = rng.uniform(0, 1);
            k[std::size_t(i)] = pick < 0.2 ? 0.0f : pick < 0.5 ? 1.0f : float(rng.uniform(0, 1));
        }
        const Premul s = random_premul(rng);
        std::vector<Premul8> want = start, got = start;
        for (int i = 0; i < n; ++i) blend_over(want[std::size_t(i)], s, k[std::size_t(i)]);
        per_pixel(got.data(), n, s, k.data());
        for (int i = 0; i < n; ++i)
            ASSERT_EQ(got[std::size_t(i)], want[std::size_t(i)])
                << name << ": trial " << trial << " pixel " << i << " of " << n << " k "
                << k[std::size_t(i)];
        EXPECT_EQ(got[std::size_t(n)], start[std::size_t(n)]) << name << ": wrote past the run";
        const float solid = k[0];
        want = start, got = start;
        for (int i = 0; i < n; ++i) blend_over(want[std::size_t(i)], s, solid);
        constant(got.data(), n, s, solid);
        for (int i = 0; i < n; ++i)
            ASSERT_EQ(got[std::size_t(i)], want[std::size_t(i)])
                << name << ": trial " << trial << " pixel " << i << " of " << n << " solid "
                << solid;
        EXPECT_EQ(got[std::size_t(n)], start[std::size_t(n)]) << name << ": wrote past the run";
    }
}

TEST(Pixel8, RunsBlendAsPixelByPixel) {
    expect_runs_blend_as_pixel_by_pixel(
        [](Premul8* d, int n, const Premul& s, const float* k) { blend_span_over(d, n, s, k); },
        [](Premul8* d, int n, const Premul& s, float k) { blend_span_over(d, n, s, k); }, "chosen");
    expect_runs_blend_as_pixel_by_pixel(
        [](Premul8* d, int n, const Premul& s, const float* k) {
            detail::blend_run(d, n, detail::OneColor{s}, detail::PerPixel{k});
        },
        [](Premul8* d, int n, const Premul& s, float k) {
            detail::blend_run(d, n, detail::OneColor{s}, detail::Constant{k});
        },
        "sse2");
}

TEST(Pixel8, Avx2RunsBlendAsPixelByPixel) {
    if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2";
    expect_runs_blend_as_pixel_by_pixel(
        [](Premul8* d, int n, const Premul& s, const float* k) {
            detail::blend_run_avx2(d, n, s, k);
        },
        [](Premul8* d, int n, const Premul& s, float k) { detail::blend_run_avx2(d, n, s, k); },
        "avx2");
}

// The same for shaded runs (a color per pixel, ShadedSpanPainter's), with
// per-pixel and constant coverage: the four- and eight-pixel bodies read each
// pixel's own color and alpha. The form blend_shaded_over chooses, the SSE2
// form and the AVX2 one (where the CPU has it).
using ShadedRun = void (*)(Premul8*, int, const Premul*, const float* k, float solid);

void expect_shaded_runs_blend_as_pixel_by_pixel(ShadedRun run, const char* name) {
    testing::Rng rng(85);
    for (int trial = 0; trial < 3000; ++trial) {
        const int n = rng.integer(0, 40);
        std::vector<Premul8> start(std::size_t(n) + 1);
        std::vector<Premul> colors(std::size_t(n) + 1);
        std::vector<float> k(std::size_t(n) + 1);
        for (int i = 0; i < n; ++i) {
            start[std::size_t(i)] = quantize(random_premul(rng));
            colors[std::size_t(i)] = random_premul(rng);
            const double pick = rng.uniform(0, 1);
            k[std::size_t(i)] = pick < 0.2 ? 0.0f : pick < 0.5 ? 1.0f : float(rng.uniform(0, 1));
        }
        for (const bool per_pixel : {true, false}) {
            std::vector<Premul8> want = start, got = start;
            for (int i = 0; i < n; ++i)
                blend_over(want[std::size_t(i)], colors[std::size_t(i)],
                           per_pixel ? k[std::size_t(i)] : k[0]);
            run(got.data(), n, colors.data(), per_pixel ? k.data() : nullptr, k[0]);
            for (int i = 0; i <= n; ++i)
                ASSERT_EQ(got[std::size_t(i)], want[std::size_t(i)])
                    << name << ": trial " << trial << " pixel " << i << " of " << n
                    << (per_pixel ? " per-pixel coverage" : " constant coverage");
        }
    }
}

TEST(Pixel8, ShadedRunsBlendAsPixelByPixel) {
    expect_shaded_runs_blend_as_pixel_by_pixel(
        [](Premul8* d, int n, const Premul* s, const float* k, float solid) {
            if (k)
                blend_shaded_over(d, n, s, k);
            else
                blend_shaded_over(d, n, s, solid);
        },
        "chosen");
    expect_shaded_runs_blend_as_pixel_by_pixel(
        [](Premul8* d, int n, const Premul* s, const float* k, float solid) {
            if (k)
                detail::blend_run(d, n, detail::Colors{s}, detail::PerPixel{k});
            else
                detail::blend_run(d, n, detail::Colors{s}, detail::Constant{solid});
        },
        "sse2");
}

TEST(Pixel8, Avx2ShadedRunsBlendAsPixelByPixel) {
    if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2";
    expect_shaded_runs_blend_as_pixel_by_pixel(
        [](Premul8* d, int n, const Premul* s, const float* k, float solid) {
            if (k)
                detail::blend_run_avx2(d, n, s, k);
            else
                detail::blend_run_avx2(d, n, s, solid);
        },
        "avx2");
}

} // namespace
} // namespace casteljau
