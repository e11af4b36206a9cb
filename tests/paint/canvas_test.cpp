// The canvas, in both pixel formats: a band view's lazy clear, and the store
// paths of composite_span, against plain per-pixel source-over.
#include "casteljau/paint/canvas.h"
#include "corpus.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

bool same(Premul a, Premul b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }
bool same(Premul8 a, Premul8 b) { return a == b; }

template <class Canvas>
class CanvasFormats : public ::testing::Test {};
using Formats = ::testing::Types<Canvas, Canvas8>;
TYPED_TEST_SUITE(CanvasFormats, Formats);

// Random spans (solid and per-pixel, opaque and translucent, some wide
// enough for streamed stores) on band views: after settle() every pixel
// equals source-over onto a canvas cleared eagerly.
TYPED_TEST(CanvasFormats, LazilyClearedBandsEqualEagerClearing) {
    using Canvas = TypeParam;
    testing::Rng rng(91);
    const int w = 4400, h = 40; // spans of 4096 8-bit pixels (16 KB) are streamed
    const Premul background{0.1f, 0.2f, 0.3f, 1.0f};
    Canvas frame(w, h), band;
    for (int trial = 0; trial < 20; ++trial) {
        frame.reset(w, h, 0, 0, Premul{9, 9, 9, 9}); // garbage the clear must replace
        Canvas eager(w, h);
        eager.fill(background);
        std::vector<float> cov(w);
        for (int y0 = 0; y0 < h; y0 += 16) {
            const int rows = std::min(16, h - y0);
            band.view_rows(frame, y0, rows, background);
            for (int k = 0; k < 12; ++k) {
                const int y = rng.integer(0, rows - 1);
                // A quarter nearly whole rows, streamed when opaque, with
                // unaligned starts and ends.
                const bool wide = rng.uniform(0, 1) < 0.25;
                const int x = wide ? rng.integer(0, 7) : rng.integer(0, w - 1);
                const int len = wide ? w - x - rng.integer(0, 7) : rng.integer(1, w - x);
                const bool opaque = rng.uniform(0, 1) < 0.6;
                const Premul c = premultiply({float(rng.uniform(0, 1)), 0.5f, 0.25f, 1.0f},
                                             opaque ? 1.0f : 0.5f);
                Span s{y, x, len, nullptr, rng.uniform(0, 1) < 0.5 ? 1.0f : 0.3f};
                if (rng.uniform(0, 1) < 0.3) {
                    for (int i = 0; i < len; ++i) cov[std::size_t(i)] = float(rng.uniform(0, 1));
                    s.coverage = cov.data();
                }
                band.composite_span(s, c);
                auto* d = eager.row(y0 + y) + x;
                for (int i = 0; i < len; ++i) blend_over(d[i], c, s.at(i));
            }
            band.settle();
        }
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                ASSERT_TRUE(same(frame.row(y)[x], eager.row(y)[x]))
                    << "trial " << trial << " at " << x << "," << y;
    }
}

// Opaque runs of every length from 0 to 80 pixels at every start within 20
// pixels (every alignment of the 16-byte stores and their overlapping ends),
// on a band whose lazy clear of the columns left of the run is as short:
// exactly the run's pixels take the color, the columns left of it the
// background, and the pixels right of it keep the frame's old value until
// settle() clears them.
TYPED_TEST(CanvasFormats, OpaqueRunsOfEveryLengthAndOffsetWriteExactlyTheirPixels) {
    using Canvas = TypeParam;
    using Pixel = typename Canvas::pixel_type;
    const Premul old{0.9f, 0.8f, 0.7f, 1.0f}, background{0.1f, 0.2f, 0.3f, 1.0f};
    const Premul color{0.25f, 0.5f, 0.75f, 1.0f};
    const int w = 128;
    Canvas frame, band;
    for (int x = 0; x < 20; ++x)
        for (int len = 0; len <= 80; ++len) {
            frame.reset(w, 1, 0, 0, old);
            band.view_rows(frame, 0, 1, background);
            band.composite_span({0, x, len, nullptr, 1.0f}, color);
            for (int i = 0; i < w; ++i) {
                const Premul want = i < x ? background : i < x + len ? color : old;
                ASSERT_TRUE(same(frame.row(0)[i], pixel_of<Pixel>(want)))
                    << "run of " << len << " from " << x << ": pixel " << i;
            }
            band.settle();
            for (int i = x + len; i < w; ++i)
                ASSERT_TRUE(same(frame.row(0)[i], pixel_of<Pixel>(background)))
                    << "run of " << len << " from " << x << ", settled: pixel " << i;
        }
}

// Coverage 0 leaves a pixel's bits as they are, whatever the color and the
// pixel (the dense sweep sends invisible columns between visible ones as 0).
TYPED_TEST(CanvasFormats, ZeroCoverageLeavesPixelsBitForBit) {
    using Pixel = typename TypeParam::pixel_type;
    testing::Rng rng(92);
    const int w = 64;
    TypeParam canvas(w, 1);
    std::vector<float> cov(w);
    for (int trial = 0; trial < 200; ++trial) {
        Pixel* row = canvas.row(0);
        for (int x = 0; x < w; ++x) {
            const float a = float(rng.uniform(0, 1));
            row[x] = pixel_of<Pixel>({a * float(rng.uniform(0, 1)), a * float(rng.uniform(0, 1)),
                                      a * float(rng.uniform(0, 1)), a});
        }
        const std::vector<Pixel> before(row, row + w);
        for (int x = 0; x < w; ++x) cov[std::size_t(x)] = x % 3 == 0 ? 0.0f : 1.0f;
        const Premul c = premultiply(
            {float(rng.uniform(0, 1)), float(rng.uniform(0, 1)), float(rng.uniform(0, 1)), 1.0f},
            trial % 2 ? 1.0f : float(rng.uniform(0, 1)));
        canvas.composite_span({0, 0, w, cov.data(), 0.0f}, c);
        for (int x = 0; x < w; x += 3)
            ASSERT_TRUE(same(canvas.row(0)[x], before[std::size_t(x)]))
                << "trial " << trial << " at " << x;
    }
}

} // namespace
} // namespace casteljau
