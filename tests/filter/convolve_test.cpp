// feConvolveMatrix: the identity kernel returns the input; box and
// asymmetric kernels against a direct double-precision reference written
// from the spec's formula (all edge modes, both alpha modes); the spec's
// worked 5 x 5 example; what each edge mode reads beyond the window; bias
// and clamping; pass-through on invalid parameters.
#include "casteljau/filter/convolve.h"
#include "filter_images.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <sstream>
#include <string>

namespace casteljau {
namespace {

using testing::same;

bool near(const Premul& a, const Premul& b, float tol) {
    return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol &&
           std::abs(a.a - b.a) <= tol;
}

std::string show(const Premul& p) {
    std::ostringstream os;
    os << "(" << p.r << ", " << p.g << ", " << p.b << ", " << p.a << ")";
    return os.str();
}

FilterImage run(const FilterImage& in, const Subregion& sub, const ConvolveMatrix& m) {
    FilterImage out;
    out.reset(in.box, in.linear);
    convolve(in, out, sub, m);
    return out;
}

// The spec's formula, literally: SOURCE read through the edge mode, kernel
// index reversed, bias times the result alpha; in double.
Premul reference(const FilterImage& in, const ConvolveMatrix& m, int X, int Y) {
    const int w = in.width(), h = in.height();
    auto source = [&](int x, int y) -> Premul {
        if (m.edge == EdgeMode::Duplicate) {
            x = std::clamp(x, 0, w - 1);
            y = std::clamp(y, 0, h - 1);
        } else if (m.edge == EdgeMode::Wrap) {
            x = ((x % w) + w) % w;
            y = ((y % h) + h) % h;
        }
        Premul p = in.get(x, y);
        if (m.preserve_alpha && p.a > 0) p = {p.r / p.a, p.g / p.a, p.b / p.a, p.a};
        if (m.preserve_alpha && !(p.a > 0)) p = {};
        return p;
    };
    double s[4] = {};
    for (int I = 0; I < m.order_y; ++I)
        for (int J = 0; J < m.order_x; ++J) {
            const double k =
                m.kernel[std::size_t((m.order_y - I - 1) * m.order_x + (m.order_x - J - 1))];
            const Premul p = source(X - m.target_x + J, Y - m.target_y + I);
            s[0] += p.r * k, s[1] += p.g * k, s[2] += p.b * k, s[3] += p.a * k;
        }
    auto clamp = [](double v, double hi) { return std::clamp(v, 0.0, hi); };
    if (m.preserve_alpha) {
        const double a = in.at(X, Y).a;
        return {float(clamp(s[0] / m.divisor + m.bias, 1) * a),
                float(clamp(s[1] / m.divisor + m.bias, 1) * a),
                float(clamp(s[2] / m.divisor + m.bias, 1) * a), float(a)};
    }
    const double a = clamp(s[3] / m.divisor + m.bias, 1);
    return {float(clamp(s[0] / m.divisor + m.bias * a, a)),
            float(clamp(s[1] / m.divisor + m.bias * a, a)),
            float(clamp(s[2] / m.divisor + m.bias * a, a)), float(a)};
}

constexpr EdgeMode kModes[] = {EdgeMode::None, EdgeMode::Duplicate, EdgeMode::Wrap};

TEST(Convolve, IdentityKernelReturnsTheInput) {
    std::mt19937 rng(1);
    const FilterImage in = testing::random_filter_image(rng, {-7, 3, 18, 23});
    ConvolveMatrix m;
    m.kernel = {0, 0, 0, 0, 1, 0, 0, 0, 0};
    const Subregion sub{0, 0, in.width(), in.height()};
    for (EdgeMode e : kModes)
        for (bool pa : {false, true}) {
            m.edge = e;
            m.preserve_alpha = pa;
            const FilterImage out = run(in, sub, m);
            for (int y = 0; y < in.height(); ++y)
                for (int x = 0; x < in.width(); ++x) {
                    // Unpremultiplying and premultiplying again may round.
                    const bool ok = pa ? near(out.at(x, y), in.at(x, y), 1e-6f)
                                       : same(out.at(x, y), in.at(x, y));
                    ASSERT_TRUE(ok)
                        << "edge " << int(e) << " preserve " << pa << " at " << x << "," << y
                        << ": " << show(out.at(x, y)) << " vs " << show(in.at(x, y));
                }
        }
}

// A 3 x 3 box, an asymmetric 3 x 2 kernel with an off-centre target (which
// shows the reversal), and a 1 x 4 kernel with a negative weight and a bias,
// in every edge and alpha mode, on random images and subregions.
TEST(Convolve, MatchesTheSpecFormula) {
    std::mt19937 rng(2);
    ConvolveMatrix box;
    box.kernel = std::vector<float>(9, 1.0f);
    box.divisor = 9;
    ConvolveMatrix asym;
    asym.order_x = 3, asym.order_y = 2, asym.target_x = 0, asym.target_y = 1;
    asym.kernel = {1, 2, 3, 4, 5, 6};
    asym.divisor = 21;
    ConvolveMatrix line;
    line.order_x = 1, line.order_y = 4, line.target_x = 0, line.target_y = 3;
    line.kernel = {2, -1, 0.5f, 1};
    line.divisor = 2.5f;
    line.bias = 0.1f;
    for (ConvolveMatrix m : {box, asym, line})
        for (EdgeMode e : kModes)
            for (bool pa : {false, true}) {
                m.edge = e;
                m.preserve_alpha = pa;
                const FilterImage in = testing::random_filter_image(rng, {5, -5, 5 + 13, -5 + 11});
                const Subregion sub{1, 2, 12, 10};
                const FilterImage out = run(in, sub, m);
                for (int y = 0; y < in.height(); ++y)
                    for (int x = 0; x < in.width(); ++x) {
                        const Premul want = sub.contains(x, y) ? reference(in, m, x, y) : Premul{};
                        ASSERT_TRUE(near(out.at(x, y), want, 2e-6f))
                            << "order " << m.order_x << "x" << m.order_y << " edge " << int(e)
                            << " preserve " << pa << " at " << x << "," << y << ": "
                            << show(out.at(x, y)) << " vs " << show(want);
                    }
            }
}

// The spec's illustration: a 5 x 5 channel, the kernel 1..9, the pixel at
// the second row and column: (9*0 + 8*20 + 7*40 + 6*100 + 5*120 + 4*140 +
// 3*200 + 2*220 + 1*240) / 45.
TEST(Convolve, SpecWorkedExample) {
    const float v[5][5] = {{0, 20, 40, 235, 235},
                           {100, 120, 140, 235, 235},
                           {200, 220, 240, 235, 235},
                           {225, 225, 255, 255, 255},
                           {225, 225, 255, 255, 255}};
    FilterImage in;
    in.reset({0, 0, 5, 5}, false);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x) in.at(x, y) = {v[y][x] / 255, 0, 0, 1};
    ConvolveMatrix m;
    m.kernel = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    m.divisor = 45;
    const FilterImage out = run(in, {1, 1, 2, 2}, m);
    const double want =
        (9 * 0 + 8 * 20 + 7 * 40 + 6 * 100 + 5 * 120 + 4 * 140 + 3 * 200 + 2 * 220 + 1 * 240) /
        45.0 / 255;
    EXPECT_NEAR(out.at(1, 1).r, want, 1e-6);
    EXPECT_EQ(out.at(1, 1).a, 1.0f);
}

// A kernel that reads the left neighbour (kernel column 2 is J = 0, i.e.
// X - 1, after the reversal): at the left edge, None reads transparent,
// Duplicate the edge pixel itself, Wrap the rightmost pixel.
TEST(Convolve, EdgeModesAtTheLeftEdge) {
    std::mt19937 rng(3);
    const FilterImage in = testing::random_filter_image(rng, {10, 10, 16, 14});
    ConvolveMatrix m;
    m.kernel = {0, 0, 0, 0, 0, 1, 0, 0, 0};
    const Subregion sub{0, 0, in.width(), in.height()};
    for (EdgeMode e : kModes) {
        m.edge = e;
        const FilterImage out = run(in, sub, m);
        for (int y = 0; y < in.height(); ++y) {
            const Premul want = e == EdgeMode::None        ? Premul{}
                                : e == EdgeMode::Duplicate ? in.at(0, y)
                                                           : in.at(in.width() - 1, y);
            ASSERT_TRUE(same(out.at(0, y), want)) << "edge " << int(e) << " row " << y;
            ASSERT_TRUE(same(out.at(3, y), in.at(2, y))) << "edge " << int(e) << " row " << y;
        }
    }
    // The same kernel turned upside down reads the neighbour above: Wrap
    // takes the bottom row at the top.
    m.kernel = {0, 0, 0, 0, 0, 0, 0, 1, 0};
    m.edge = EdgeMode::Wrap;
    const FilterImage out = run(in, sub, m);
    for (int x = 0; x < in.width(); ++x)
        ASSERT_TRUE(same(out.at(x, 0), in.at(x, in.height() - 1))) << "column " << x;
}

// Results are clamped: alpha to [0, 1], colors to [0, alpha]; the bias is
// scaled by the result alpha for premultiplied colors.
TEST(Convolve, BiasAndClamping) {
    std::mt19937 rng(4);
    const FilterImage in = testing::random_filter_image(rng, {0, 0, 9, 7});
    const Subregion sub{0, 0, 9, 7};
    ConvolveMatrix zero;
    zero.kernel = std::vector<float>(9, 0.0f);
    zero.bias = 0.5f;
    FilterImage out = run(in, sub, zero);
    for (const Premul& p : out.px)
        ASSERT_TRUE(same(p, Premul{0.25f, 0.25f, 0.25f, 0.5f})) << show(p);
    ConvolveMatrix loud; // sharpening with a large gain: overshoots both ways
    loud.kernel = {-4, -4, -4, -4, 40, -4, -4, -4, -4};
    loud.bias = 0.2f;
    for (bool pa : {false, true}) {
        loud.preserve_alpha = pa;
        out = run(in, sub, loud);
        for (const Premul& p : out.px) {
            ASSERT_GE(p.a, 0.0f);
            ASSERT_LE(p.a, 1.0f);
            for (float c : {p.r, p.g, p.b}) {
                ASSERT_GE(c, 0.0f) << show(p);
                ASSERT_LE(c, p.a) << show(p);
            }
        }
    }
}

// A window cut from a larger one gives the same bits wherever the kernel's
// footprint stays inside the cut window, whatever the edge mode.
TEST(Convolve, CutWindowMatchesAwayFromTheCut) {
    std::mt19937 rng(6);
    const FilterImage big = testing::random_filter_image(rng, {0, 0, 40, 30});
    FilterImage cut;
    cut.reset({7, 5, 31, 26}, false);
    for (int y = 0; y < cut.height(); ++y)
        for (int x = 0; x < cut.width(); ++x) cut.at(x, y) = big.at(x + 7, y + 5);
    ConvolveMatrix m;
    m.order_x = 4, m.order_y = 3, m.target_x = 2, m.target_y = 0;
    m.kernel = {0.3f, -1, 2, 0.7f, 1, 1, -0.5f, 3, 0.1f, 0.2f, 0.3f, 0.4f};
    m.divisor = 7;
    m.bias = 0.05f;
    for (EdgeMode e : kModes)
        for (bool pa : {false, true}) {
            m.edge = e;
            m.preserve_alpha = pa;
            const FilterImage a = run(big, {0, 0, big.width(), big.height()}, m);
            const FilterImage b = run(cut, {0, 0, cut.width(), cut.height()}, m);
            for (int y = 0; y < cut.height() - 2; ++y)
                for (int x = 2; x < cut.width() - 1; ++x)
                    ASSERT_TRUE(same(b.at(x, y), a.at(x + 7, y + 5))) << x << "," << y;
        }
}

TEST(Convolve, InvalidParametersPassThrough) {
    std::mt19937 rng(5);
    const FilterImage in = testing::random_filter_image(rng, {0, 0, 8, 8});
    const Subregion sub{2, 2, 6, 7};
    ConvolveMatrix m;
    m.kernel = {1, 2, 3}; // not 3 x 3
    FilterImage out = run(in, sub, m);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            ASSERT_TRUE(same(out.at(x, y), sub.contains(x, y) ? in.at(x, y) : Premul{}));
    m.kernel = std::vector<float>(9, 1.0f);
    m.target_x = 3; // outside the kernel
    EXPECT_FALSE(valid_kernel(m));
    m.target_x = 1;
    m.divisor = 0;
    EXPECT_FALSE(valid_kernel(m));
    m.divisor = 9;
    EXPECT_TRUE(valid_kernel(m));
}

} // namespace
} // namespace casteljau
