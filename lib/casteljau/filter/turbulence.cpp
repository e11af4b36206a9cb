// feTurbulence (Filter Effects 1, "Filter primitive feTurbulence",
// #feTurbulenceElement): the spec's reference C code, rewritten, giving the
// same bits (tests/filter/turbulence_test.cpp compares against the spec's
// code itself).
//
// For channel k (R, G, B, A) at point p (user space):
//   turbulence_k(p) = sum_{o=0}^{octaves-1} f(noise2_k(p * freq * 2^o)) / 2^o
// with f the identity (fractalNoise) or |.| (turbulence); noise2 is 2D
// Perlin gradient noise on a 256-lattice: the four lattice gradients
// around p dotted with p's offsets from them, blended by the cubic
// s(t) = t^2 (3 - 2t). Lattice gradients and the permutation come from the
// Park-Miller generator r <- 16807 r mod (2^31 - 1), seeded with the seed
// truncated towards zero (the spec: "truncated, i.e. rounded to the closest
// integer value towards zero"; resvg and Skia do the same), drawn for R, then
// G, B and A. The color or alpha value is (sum + 1) / 2 for fractalNoise and
// the sum for turbulence, clamped to [0, 1].
//
// Stitching (stitchTiles="stitch"): each base frequency is moved to the
// nearer (by ratio) of floor(w f) / w and ceil(w f) / w for the tile's width
// w (height for y), and lattice coordinates past the tile's right or bottom
// edge wrap back by the tile's size in lattice cells, doubled each octave.
//
// Which version of the code: the spec's text as it stood through the
// published drafts, where init() redraws a gradient that comes out (0, 0)
// (otherwise a division by zero). The current editor's draft also redraws
// gradients longer than 1 (fxtf-drafts issue 115); no engine (Chrome, Firefox,
// WebKit, resvg) does, and it changes every image, so it is not followed.
//
// Invariants and deviations: the lattice arithmetic is 64-bit and saturating
// where the spec's is int (overflowing, hence undefined, for many octaves or
// far coordinates); within int range the values are the same. More than
// kMaxOctaves octaves count as kMaxOctaves: each octave adds half the
// previous, so the rest lies below 2^-32, under a float's resolution of the
// result. Each pixel depends on its own point only, so any window gives the
// same bits.
#include "casteljau/filter/turbulence.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace casteljau {

namespace {

using i64 = std::int64_t;

constexpr i64 kRandM = 2147483647; // 2^31 - 1, the generator's prime modulus
constexpr i64 kRandA = 16807;      // 7^5, a primitive root of kRandM
constexpr i64 kRandQ = 127773;     // kRandM / kRandA and kRandM % kRandA: Schrage's
constexpr i64 kRandR = 2836;       // method, a * r mod m without overflow
constexpr int kB = 0x100;          // lattice size (BSize)
constexpr int kBM = 0xff;          // kB - 1, the lattice index mask
constexpr int kPerlinN = 0x1000;   // added so that truncation floors for p > -4096
constexpr int kMaxOctaves = 32;
constexpr i64 kLimit = i64(1) << 62; // saturation bound of the lattice arithmetic

i64 setup_seed(i64 seed) {
    if (seed <= 0) seed = -(seed % (kRandM - 1)) + 1;
    if (seed > kRandM - 1) seed = kRandM - 1;
    return seed;
}

i64 next_random(i64 seed) {
    i64 r = kRandA * (seed % kRandQ) - kRandR * (seed / kRandQ);
    if (r <= 0) r += kRandM;
    return r;
}

// (i64)v, saturated to [-kLimit, kLimit]; NaN gives 0.
i64 to_i64(double v) {
    if (!(v == v)) return 0;
    return i64(std::clamp(v, -double(kLimit), double(kLimit)));
}

i64 twice(i64 v) { return std::clamp(v, -kLimit / 2, kLimit / 2) * 2; }

struct Tables {
    int lattice[kB + kB + 2];
    double gradient[4][kB + kB + 2][2];
};

// The spec's init(lSeed).
void init(Tables& t, i64 seed) {
    seed = setup_seed(seed);
    for (int k = 0; k < 4; ++k)
        for (int i = 0; i < kB; ++i) {
            t.lattice[i] = i;
            double* g = t.gradient[k][i];
            do {
                for (int j = 0; j < 2; ++j) {
                    seed = next_random(seed);
                    g[j] = double(seed % (kB + kB) - kB) / kB;
                }
            } while (g[0] == 0 && g[1] == 0);
            const double s = std::sqrt(g[0] * g[0] + g[1] * g[1]);
            g[0] /= s;
            g[1] /= s;
        }
    for (int i = kB - 1; i > 0; --i) {
        const int k = t.lattice[i];
        seed = next_random(seed);
        const int j = int(seed % kB);
        t.lattice[i] = t.lattice[j];
        t.lattice[j] = k;
    }
    for (int i = 0; i < kB + 2; ++i) {
        t.lattice[kB + i] = t.lattice[i];
        for (int k = 0; k < 4; ++k)
            for (int j = 0; j < 2; ++j) t.gradient[k][kB + i][j] = t.gradient[k][i][j];
    }
}

struct Stitch {
    bool on = false;
    i64 width = 0, height = 0;  // how much to subtract to wrap
    i64 wrap_x = 0, wrap_y = 0; // the smallest lattice coordinate that wraps
};

// One axis of noise2's lattice set-up: cell corners b0, b1 (masked) and the
// offsets r0, r1 of v from them.
struct Axis {
    int b0, b1;
    double r0, r1;
};

Axis axis(double v, bool stitch, i64 wrap, i64 size) {
    const double t = v + kPerlinN;
    i64 b0 = to_i64(t), b1 = b0 + 1;
    const double r0 = t - double(b0);
    if (stitch) {
        if (b0 >= wrap) b0 -= size;
        if (b1 >= wrap) b1 -= size;
    }
    return {int(b0 & kBM), int(b1 & kBM), r0, r0 - 1.0};
}

// The spec's noise2(nColorChannel, vec, pStitchInfo).
double noise2(const Tables& t, int k, double vx, double vy, const Stitch& st) {
    const Axis x = axis(vx, st.on, st.wrap_x, st.width);
    const Axis y = axis(vy, st.on, st.wrap_y, st.height);
    const int i = t.lattice[x.b0], j = t.lattice[x.b1];
    const double* g00 = t.gradient[k][t.lattice[i + y.b0]];
    const double* g10 = t.gradient[k][t.lattice[j + y.b0]];
    const double* g01 = t.gradient[k][t.lattice[i + y.b1]];
    const double* g11 = t.gradient[k][t.lattice[j + y.b1]];
    const double sx = x.r0 * x.r0 * (3. - 2. * x.r0);
    const double sy = y.r0 * y.r0 * (3. - 2. * y.r0);
    double u = x.r0 * g00[0] + y.r0 * g00[1];
    double v = x.r1 * g10[0] + y.r0 * g10[1];
    const double a = u + sx * (v - u);
    u = x.r0 * g01[0] + y.r1 * g01[1];
    v = x.r1 * g11[0] + y.r1 * g11[1];
    const double b = u + sx * (v - u);
    return a + sy * (b - a);
}

// The stitching adjustment of one base frequency to a tile of size w.
double stitched_frequency(double f, double w) {
    if (f == 0.0) return f;
    const double lo = std::floor(w * f) / w, hi = std::ceil(w * f) / w;
    return f / lo < hi / f ? lo : hi;
}

// Everything of the spec's turbulence() that does not depend on the point.
struct Setup {
    double fx = 0, fy = 0;
    Stitch stitch;
};

Setup setup(const Turbulence& t, const Rect& tile) {
    Setup s{t.base_x, t.base_y, {}};
    if (!t.stitch) return s;
    s.fx = stitched_frequency(s.fx, tile.width());
    s.fy = stitched_frequency(s.fy, tile.height());
    s.stitch.on = true;
    s.stitch.width = to_i64(tile.width() * s.fx + 0.5);
    s.stitch.wrap_x = to_i64(tile.x0 * s.fx + kPerlinN + double(s.stitch.width));
    s.stitch.height = to_i64(tile.height() * s.fy + 0.5);
    s.stitch.wrap_y = to_i64(tile.y0 * s.fy + kPerlinN + double(s.stitch.height));
    return s;
}

// The spec's turbulence() for channel k at point p.
double sum_octaves(const Tables& tab, const Turbulence& t, const Setup& s, int k, Point p) {
    Stitch st = s.stitch;
    double sum = 0, vx = p.x * s.fx, vy = p.y * s.fy, ratio = 1;
    const int octaves = std::min(t.octaves, kMaxOctaves);
    for (int o = 0; o < octaves; ++o) {
        const double n = noise2(tab, k, vx, vy, st);
        sum += t.fractal_noise ? n / ratio : std::fabs(n) / ratio;
        vx *= 2;
        vy *= 2;
        ratio *= 2;
        if (st.on) {
            st.width = twice(st.width);
            st.wrap_x = twice(st.wrap_x) - kPerlinN;
            st.height = twice(st.height);
            st.wrap_y = twice(st.wrap_y) - kPerlinN;
        }
    }
    return sum;
}

float channel_value(double sum, bool fractal) {
    const double v = fractal ? (sum + 1) / 2 : sum;
    return float(v > 0 ? (v < 1 ? v : 1) : 0);
}

} // namespace

void turbulence(FilterImage& out, const Subregion& sub, const Turbulence& t,
                const Affine& device_to_user, const Rect& tile_user) noexcept {
    if (t.octaves <= 0 || sub.empty()) return;
    Tables tab;
    // Truncation towards zero; seeds beyond +-2^62 saturate (the spec's long
    // would overflow).
    init(tab, to_i64(std::trunc(t.seed)));
    const Setup s = setup(t, tile_user);
    for (int y = sub.y0; y < sub.y1; ++y)
        for (int x = sub.x0; x < sub.x1; ++x) {
            const Point p = device_to_user * Point{double(out.box.x0 + x), double(out.box.y0 + y)};
            float c[4];
            for (int k = 0; k < 4; ++k)
                c[k] = channel_value(sum_octaves(tab, t, s, k, p), t.fractal_noise);
            out.at(x, y) = {c[0] * c[3], c[1] * c[3], c[2] * c[3], c[3]};
        }
}

} // namespace casteljau
