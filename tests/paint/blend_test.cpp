// Blend modes: every mode against a double-precision reference written here
// from Compositing and Blending Level 1 (10.1, 10.2, and simple alpha
// compositing with the blended color), the compositing identities, the
// spec's own identities between modes, and composite_layer against
// per-pixel blend() on both pixel formats.
#include "casteljau/paint/blend.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace casteljau {
namespace {

constexpr std::array<BlendMode, 16> kModes = {
    BlendMode::Normal,    BlendMode::Multiply,   BlendMode::Screen,     BlendMode::Overlay,
    BlendMode::Darken,    BlendMode::Lighten,    BlendMode::ColorDodge, BlendMode::ColorBurn,
    BlendMode::HardLight, BlendMode::SoftLight,  BlendMode::Difference, BlendMode::Exclusion,
    BlendMode::Hue,       BlendMode::Saturation, BlendMode::Color,      BlendMode::Luminosity};
constexpr std::array<const char*, 16> kNames = {
    "normal",      "multiply",   "screen",     "overlay",    "darken",     "lighten",
    "color-dodge", "color-burn", "hard-light", "soft-light", "difference", "exclusion",
    "hue",         "saturation", "color",      "luminosity"};

const char* name(BlendMode m) { return kNames[std::size_t(m)]; }

std::string show(const Premul& p) {
    std::ostringstream o;
    o.precision(9);
    o << "{" << p.r << ", " << p.g << ", " << p.b << ", a " << p.a << "}";
    return o.str();
}

float channel(const Premul& p, int i) { return i == 0 ? p.r : i == 1 ? p.g : i == 2 ? p.b : p.a; }
float channel(const Premul8& p, int i) {
    return float(i == 0 ? p.r : i == 1 ? p.g : i == 2 ? p.b : p.a);
}

bool same(const Premul& a, const Premul& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

// A valid premultiplied color, often at the values where the modes' formulas
// branch (0, 1/4, 1/2, 1), sometimes gray, sometimes opaque or transparent.
Premul random_color(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    constexpr float kEdges[] = {0.0f, 0.25f, 0.5f, 1.0f};
    const auto straight = [&] {
        return u(rng) < 0.2f ? kEdges[std::uniform_int_distribution<>(0, 3)(rng)] : u(rng);
    };
    const float p = u(rng);
    const float a = p < 0.2f ? 1.0f : p < 0.3f ? 0.0f : u(rng);
    const float r = straight();
    const bool gray = u(rng) < 0.1f;
    const float g = gray ? r : straight(), b = gray ? r : straight();
    return premultiply({r, g, b, 1.0f}, a);
}

Premul opaque(std::mt19937& rng) {
    Premul c = random_color(rng);
    while (c.a == 0) c = random_color(rng);
    return {c.r / c.a, c.g / c.a, c.b / c.a, 1.0f};
}

// The reference, in double, literally as the spec writes it.
using C3 = std::array<double, 3>;

double ref_channel(BlendMode m, double cb, double cs) {
    switch (m) {
    case BlendMode::Normal:
        return cs;
    case BlendMode::Multiply:
        return cb * cs;
    case BlendMode::Screen:
        return cb + cs - cb * cs;
    case BlendMode::Overlay:
        return ref_channel(BlendMode::HardLight, cs, cb);
    case BlendMode::Darken:
        return std::min(cb, cs);
    case BlendMode::Lighten:
        return std::max(cb, cs);
    case BlendMode::ColorDodge:
        if (cb == 0) return 0;
        if (cs == 1) return 1;
        return std::min(1.0, cb / (1 - cs));
    case BlendMode::ColorBurn:
        if (cb == 1) return 1;
        if (cs == 0) return 0;
        return 1 - std::min(1.0, (1 - cb) / cs);
    case BlendMode::HardLight:
        if (cs <= 0.5) return ref_channel(BlendMode::Multiply, cb, 2 * cs);
        return ref_channel(BlendMode::Screen, cb, 2 * cs - 1);
    case BlendMode::SoftLight: {
        if (cs <= 0.5) return cb - (1 - 2 * cs) * cb * (1 - cb);
        const double d = cb <= 0.25 ? ((16 * cb - 12) * cb + 4) * cb : std::sqrt(cb);
        return cb + (2 * cs - 1) * (d - cb);
    }
    case BlendMode::Difference:
        return std::fabs(cb - cs);
    case BlendMode::Exclusion:
        return cb + cs - 2 * cb * cs;
    default:
        return std::numeric_limits<double>::quiet_NaN(); // not separable
    }
}

double Lum(const C3& c) { return 0.3 * c[0] + 0.59 * c[1] + 0.11 * c[2]; }

C3 ClipColor(C3 c) {
    const double l = Lum(c);
    const double n = std::min({c[0], c[1], c[2]}), x = std::max({c[0], c[1], c[2]});
    if (n < 0)
        for (double& v : c) v = l + (v - l) * l / (l - n);
    if (x > 1)
        for (double& v : c) v = l + (v - l) * (1 - l) / (x - l);
    return c;
}

C3 SetLum(const C3& c, double l) {
    const double d = l - Lum(c);
    return ClipColor({c[0] + d, c[1] + d, c[2] + d});
}

double Sat(const C3& c) { return std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]}); }

// With the channels sorted, as the spec writes it.
C3 SetSat(const C3& c, double s) {
    std::array<int, 3> i = {0, 1, 2};
    std::sort(i.begin(), i.end(),
              [&](int p, int q) { return c[std::size_t(p)] < c[std::size_t(q)]; });
    const auto lo = std::size_t(i[0]), mid = std::size_t(i[1]), hi = std::size_t(i[2]);
    C3 o{};
    if (c[hi] > c[lo]) {
        o[mid] = (c[mid] - c[lo]) * s / (c[hi] - c[lo]);
        o[hi] = s;
    }
    return o;
}

C3 ref_blend(BlendMode m, const C3& cb, const C3& cs) {
    switch (m) {
    case BlendMode::Hue:
        return SetLum(SetSat(cs, Sat(cb)), Lum(cb));
    case BlendMode::Saturation:
        return SetLum(SetSat(cb, Sat(cs)), Lum(cb));
    case BlendMode::Color:
        return SetLum(cs, Lum(cb));
    case BlendMode::Luminosity:
        return SetLum(cb, Lum(cs));
    default:
        break;
    }
    C3 o;
    for (std::size_t i = 0; i < 3; ++i) o[i] = ref_channel(m, cb[i], cs[i]);
    return o;
}

std::array<double, 4> reference(const Premul& d, const Premul& s, BlendMode m) {
    const double ab = d.a, as = s.a;
    const C3 pb{d.r, d.g, d.b}, ps{s.r, s.g, s.b};
    C3 cb{}, cs{};
    for (std::size_t i = 0; i < 3; ++i) {
        cb[i] = ab > 0 ? pb[i] / ab : 0;
        cs[i] = as > 0 ? ps[i] / as : 0;
    }
    const C3 b = ref_blend(m, cb, cs);
    std::array<double, 4> o;
    for (std::size_t i = 0; i < 3; ++i) o[i] = ps[i] * (1 - ab) + pb[i] * (1 - as) + as * ab * b[i];
    o[3] = as + ab * (1 - as);
    return o;
}

// (a) Every mode within 1e-5 of the reference.
TEST(BlendModes, MatchTheSpecReference) {
    std::mt19937 rng(1101);
    for (BlendMode m : kModes) {
        double worst = 0;
        for (int trial = 0; trial < 20000; ++trial) {
            const Premul d = random_color(rng), s = random_color(rng);
            const Premul o = blend(d, s, m);
            const auto want = reference(d, s, m);
            for (int i = 0; i < 4; ++i) {
                const double err = std::fabs(double(channel(o, i)) - want[std::size_t(i)]);
                worst = std::max(worst, err);
                ASSERT_LE(err, 1e-5) << name(m) << " trial " << trial << " channel " << i
                                     << ": backdrop " << show(d) << " source " << show(s)
                                     << " gives " << show(o) << ", want " << want[std::size_t(i)];
            }
        }
        std::ostringstream w;
        w << worst;
        RecordProperty(std::string("worst_") + name(m), w.str());
    }
}

// (b) Normal is source-over, bit for bit.
TEST(BlendModes, NormalIsBlendOverExactly) {
    std::mt19937 rng(1102);
    for (int trial = 0; trial < 20000; ++trial) {
        const Premul d = random_color(rng), s = random_color(rng);
        Premul want = d;
        blend_over(want, s, 1.0f);
        const Premul o = blend(d, s, BlendMode::Normal);
        ASSERT_TRUE(same(o, want)) << "trial " << trial << ": backdrop " << show(d) << " source "
                                   << show(s) << " gives " << show(o) << ", want " << show(want);
    }
}

// (c), (d) Where either side is transparent there is nothing to blend: the
// other comes through unchanged, in every mode.
TEST(BlendModes, TransparentSideLeavesTheOtherExactly) {
    std::mt19937 rng(1103);
    const Premul clear{};
    for (BlendMode m : kModes)
        for (int trial = 0; trial < 2000; ++trial) {
            const Premul c = random_color(rng);
            const Premul over_clear = blend(clear, c, m), under_clear = blend(c, clear, m);
            ASSERT_TRUE(same(over_clear, c)) << name(m) << ": source " << show(c)
                                             << " over transparent gives " << show(over_clear);
            ASSERT_TRUE(same(under_clear, c))
                << name(m) << ": transparent over " << show(c) << " gives " << show(under_clear);
        }
}

// (e) The alpha is source-over's in every mode, and the premultiplied
// channels stay within [0, alpha].
TEST(BlendModes, AlphaIsSourceOverAndChannelsStayInRange) {
    std::mt19937 rng(1104);
    for (BlendMode m : kModes)
        for (int trial = 0; trial < 5000; ++trial) {
            const Premul d = random_color(rng), s = random_color(rng);
            const Premul o = blend(d, s, m);
            const double want = double(s.a) + double(d.a) * (1 - double(s.a));
            ASSERT_NEAR(o.a, want, 1e-7) << name(m) << ": " << show(d) << " under " << show(s);
            for (int i = 0; i < 3; ++i) {
                ASSERT_GE(channel(o, i), 0.0f) << name(m) << " channel " << i << " " << show(o);
                ASSERT_LE(channel(o, i), o.a) << name(m) << " channel " << i << " " << show(o);
            }
        }
}

void expect_near(const Premul& got, const Premul& want, const std::string& what,
                 float tol = 1e-6f) {
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(channel(got, i), channel(want, i), tol)
            << what << " channel " << i << ": " << show(got) << ", want " << show(want);
}

// (f) The spec's identities: white is multiply's identity and black
// screen's, a color's difference from itself is black, overlay is
// hard-light with the layers swapped, luminosity is color with them swapped,
// the commutative modes commute, and the non-separable modes keep the
// luminosity they take.
TEST(BlendModes, SpecIdentities) {
    std::mt19937 rng(1105);
    const Premul white{1, 1, 1, 1}, black{0, 0, 0, 1};
    for (int trial = 0; trial < 2000; ++trial) {
        const Premul b = opaque(rng), s = opaque(rng), any = random_color(rng);
        const std::string at = "trial " + std::to_string(trial) + " " + show(b) + " " + show(s);
        expect_near(blend(b, white, BlendMode::Multiply), b, "multiply by white " + at);
        expect_near(blend(white, any, BlendMode::Multiply), blend(white, any, BlendMode::Normal),
                    "white multiplied by " + show(any));
        expect_near(blend(b, black, BlendMode::Screen), b, "screen with black " + at);
        expect_near(blend(black, any, BlendMode::Screen), blend(black, any, BlendMode::Normal),
                    "black screened by " + show(any));
        expect_near(blend(b, b, BlendMode::Difference), black, "difference with itself " + at);
        expect_near(blend(b, s, BlendMode::Overlay), blend(s, b, BlendMode::HardLight),
                    "overlay / hard-light " + at);
        expect_near(blend(b, s, BlendMode::Luminosity), blend(s, b, BlendMode::Color),
                    "luminosity / color " + at);
        for (BlendMode m : {BlendMode::Multiply, BlendMode::Screen, BlendMode::Darken,
                            BlendMode::Lighten, BlendMode::Difference, BlendMode::Exclusion})
            expect_near(blend(b, s, m), blend(s, b, m), std::string(name(m)) + " commutes " + at);
        // SetLum's clip moves the channels toward the luminosity, keeping it.
        const auto lum = [](const Premul& c) { return Lum({c.r, c.g, c.b}); };
        for (BlendMode m : {BlendMode::Hue, BlendMode::Saturation, BlendMode::Color})
            EXPECT_NEAR(lum(blend(b, s, m)), lum(b), 1e-5) << name(m) << " " << at;
        EXPECT_NEAR(lum(blend(b, s, BlendMode::Luminosity)), lum(s), 1e-5) << at;
    }
}

// The edge cases of 10.1, on opaque grays: color-dodge of a black backdrop
// is black even under a white source, color-burn of a white backdrop is
// white even under a black source, and soft-light with a mid-gray source
// leaves the backdrop.
TEST(BlendModes, DodgeBurnAndSoftLightEdges) {
    const auto gray = [](float v) { return Premul{v, v, v, 1}; };
    expect_near(blend(gray(0), gray(1), BlendMode::ColorDodge), gray(0), "dodge(0, 1)");
    expect_near(blend(gray(0.5f), gray(1), BlendMode::ColorDodge), gray(1), "dodge(0.5, 1)");
    expect_near(blend(gray(0.25f), gray(0.5f), BlendMode::ColorDodge), gray(0.5f),
                "dodge(0.25, 0.5)");
    expect_near(blend(gray(1), gray(0), BlendMode::ColorBurn), gray(1), "burn(1, 0)");
    expect_near(blend(gray(0.5f), gray(0), BlendMode::ColorBurn), gray(0), "burn(0.5, 0)");
    expect_near(blend(gray(0.75f), gray(0.5f), BlendMode::ColorBurn), gray(0.5f),
                "burn(0.75, 0.5)");
    for (float v : {0.0f, 0.1f, 0.25f, 0.6f, 1.0f})
        expect_near(blend(gray(v), gray(0.5f), BlendMode::SoftLight), gray(v),
                    "soft-light(" + std::to_string(v) + ", 0.5)");
}

// (h) Transparent, denormal-alpha, black, white and denormal colors, in every
// combination and mode: always finite, within [0, alpha].
TEST(BlendModes, NoNanAtTheEdges) {
    std::vector<Premul> colors;
    for (float a : {0.0f, 1e-40f, 1e-30f, 1e-7f, 0.5f, 1.0f})
        for (int k = 0; k < 64; ++k) {
            constexpr float kStraight[] = {0.0f, 1e-40f, 0.5f, 1.0f};
            const auto v = [&](int i) { return kStraight[i] * a; };
            colors.push_back({v(k % 4), v(k / 4 % 4), v(k / 16), a});
        }
    for (BlendMode m : kModes)
        for (const Premul& d : colors)
            for (const Premul& s : colors) {
                const Premul o = blend(d, s, m);
                for (int i = 0; i < 4; ++i)
                    ASSERT_TRUE(std::isfinite(channel(o, i)))
                        << name(m) << ": " << show(d) << " under " << show(s) << " gives "
                        << show(o);
                for (int i = 0; i < 3; ++i)
                    ASSERT_TRUE(channel(o, i) >= 0 && channel(o, i) <= o.a)
                        << name(m) << ": " << show(d) << " under " << show(s) << " gives "
                        << show(o);
            }
}

TEST(BlendModes, ParsesTheCssKeywords) {
    for (BlendMode m : kModes) {
        const auto parsed = parse_blend_mode(name(m));
        ASSERT_TRUE(parsed.has_value()) << name(m);
        EXPECT_EQ(*parsed, m) << name(m);
    }
    EXPECT_EQ(parse_blend_mode("Color-Dodge"), BlendMode::ColorDodge);
    EXPECT_EQ(parse_blend_mode("MULTIPLY"), BlendMode::Multiply);
    for (const char* bad : {"", "plus-lighter", "multiply ", " multiply", "colordodge",
                            "color_dodge", "lum", "luminosityx"})
        EXPECT_FALSE(parse_blend_mode(bad).has_value()) << "'" << bad << "'";
}

TEST(BlendModes, PlusLighterIsTheClampedSumAndMixBlendModeOnly) {
    std::mt19937 rng(1108);
    for (int i = 0; i < 2000; ++i) {
        const Premul d = random_color(rng), s = random_color(rng);
        const Premul o = blend(d, s, BlendMode::PlusLighter);
        const Premul want{std::min(1.0f, d.r + s.r), std::min(1.0f, d.g + s.g),
                          std::min(1.0f, d.b + s.b), std::min(1.0f, d.a + s.a)};
        for (int k = 0; k < 4; ++k)
            ASSERT_EQ(channel(o, k), channel(want, k)) << show(d) << show(s);
        for (int k = 0; k < 3; ++k) ASSERT_LE(channel(o, k), o.a) << show(d) << show(s);
    }
    EXPECT_EQ(parse_mix_blend_mode("plus-lighter"), BlendMode::PlusLighter);
    EXPECT_EQ(parse_mix_blend_mode("Plus-Lighter"), BlendMode::PlusLighter);
    for (BlendMode m : kModes) EXPECT_EQ(parse_mix_blend_mode(name(m)), m) << name(m);
    EXPECT_FALSE(parse_mix_blend_mode("plus-darker").has_value());
    EXPECT_FALSE(parse_blend_mode("plus-lighter").has_value()); // feBlend's <blend-mode>
}

// (g) composite_layer on both pixel formats.
template <class Canvas>
class BlendLayer : public ::testing::Test {};
using Formats = ::testing::Types<Canvas, Canvas8>;
TYPED_TEST_SUITE(BlendLayer, Formats);

template <class Canvas>
Canvas random_canvas(std::mt19937& rng, int w, int h, int ox, int oy) {
    using Pixel = typename Canvas::pixel_type;
    Canvas c(w, h, ox, oy);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) c.row(y)[x] = pixel_of<Pixel>(random_color(rng));
    return c;
}

// A layer hanging off the target (left and bottom, then right and top)
// changes exactly the pixels it covers, each to blend() of the pixel and the
// layer's pixel scaled by the opacity: equal for float pixels, within the
// one rounding for 8-bit ones.
TYPED_TEST(BlendLayer, MatchesPerPixelBlend) {
    using Canvas = TypeParam;
    constexpr bool bytes = std::is_same_v<Canvas, Canvas8>;
    std::mt19937 rng(1106);
    const float opacity = 0.7f;
    struct Place {
        int ox, oy;
    };
    for (const Place at : {Place{0, 10}, Place{18, 1}})
        for (BlendMode m : kModes) {
            const Canvas before = random_canvas<Canvas>(rng, 20, 14, 5, 3);
            const Canvas layer = random_canvas<Canvas>(rng, 12, 10, at.ox, at.oy);
            Canvas target = before;
            composite_layer(target, layer, opacity, m);
            for (int y = 0; y < target.height(); ++y)
                for (int x = 0; x < target.width(); ++x) {
                    const auto& got = target.row(y)[x];
                    const auto& was = before.row(y)[x];
                    const int lx = x + 5 - at.ox, ly = y + 3 - at.oy;
                    const std::string where = std::string(name(m)) + " at (" + std::to_string(x) +
                                              ", " + std::to_string(y) + ")";
                    if (lx < 0 || ly < 0 || lx >= layer.width() || ly >= layer.height()) {
                        for (int i = 0; i < 4; ++i)
                            ASSERT_EQ(channel(got, i), channel(was, i)) << where << " outside";
                        continue;
                    }
                    const Premul c = to_premul(layer.row(ly)[lx]);
                    const Premul want =
                        blend(to_premul(was),
                              {opacity * c.r, opacity * c.g, opacity * c.b, opacity * c.a}, m);
                    for (int i = 0; i < 4; ++i) {
                        if constexpr (bytes)
                            ASSERT_LE(std::fabs(channel(got, i) - 255.0f * channel(want, i)),
                                      0.5f + 1e-3f)
                                << where << " channel " << i << " want " << show(want);
                        else
                            ASSERT_NEAR(channel(got, i), channel(want, i), 1e-6f)
                                << where << " channel " << i << " want " << show(want);
                    }
                }
        }
}

// Normal is the canvas's own composite_layer, bit for bit (the 8-bit canvas
// rounds its own way).
TYPED_TEST(BlendLayer, NormalIsTheCanvasComposite) {
    using Canvas = TypeParam;
    std::mt19937 rng(1107);
    const Canvas before = random_canvas<Canvas>(rng, 20, 14, 5, 3);
    const Canvas layer = random_canvas<Canvas>(rng, 12, 10, 0, 10);
    Canvas got = before, want = before;
    composite_layer(got, layer, 0.6f, BlendMode::Normal);
    want.composite_layer(layer, 0.6f);
    for (int y = 0; y < got.height(); ++y)
        for (int x = 0; x < got.width(); ++x)
            for (int i = 0; i < 4; ++i)
                ASSERT_EQ(channel(got.row(y)[x], i), channel(want.row(y)[x], i))
                    << "(" << x << ", " << y << ") channel " << i;
}

} // namespace
} // namespace casteljau
