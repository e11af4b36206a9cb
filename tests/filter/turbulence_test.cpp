// feTurbulence against the spec's own reference C code (copied below), every
// channel compared bit for bit (==) on a 64 x 64 window under a scaling,
// translating (and, once, rotating) device-to-user map, for several seeds,
// frequencies and octave counts, both noise types, stitching on and off; the
// subregion; numOctaves <= 0; the seed's truncation.
#include "casteljau/filter/turbulence.h"

#include <cmath>
#include <cstddef>
#include <gtest/gtest.h>
#include <math.h>
#include <set>

// ---------------------------------------------------------------------------
// The spec's code: Filter Effects Module Level 1, "Filter primitive
// feTurbulence" (w3c/fxtf-drafts, filter-effects/Overview.bs, e.g. at commit
// 5d6ec988), verbatim but for what C++ requires: `static uLatticeSelector`
// gains its implicit `int`, `register i, j;` becomes `int i, j;`, and it
// lives in a namespace of its own so that random() does not meet POSIX's.
// (The current editor's draft adds, in init(), "if (s > 1) { i--; continue; }",
// redrawing gradients longer than 1; no engine does, and Casteljau follows
// the engines: see turbulence.cpp.)
namespace {
namespace spec {

// clang-format off

/* Produces results in the range [1, 2**31 - 2].
Algorithm is: r = (a * r) mod m
where a = 16807 and m = 2**31 - 1 = 2147483647
See [Park & Miller], CACM vol. 31 no. 10 p. 1195, Oct. 1988
To test: the algorithm should produce the result 1043618065
as the 10,000th generated number if the original seed is 1.
*/
#define RAND_m 2147483647 /* 2**31 - 1 */
#define RAND_a 16807 /* 7**5; primitive root of m */
#define RAND_q 127773 /* m / a */
#define RAND_r 2836 /* m % a */
long setup_seed(long lSeed)
{
  if (lSeed <= 0) lSeed = -(lSeed % (RAND_m - 1)) + 1;
  if (lSeed > RAND_m - 1) lSeed = RAND_m - 1;
  return lSeed;
}
long random(long lSeed)
{
  long result;
  result = RAND_a * (lSeed % RAND_q) - RAND_r * (lSeed / RAND_q);
  if (result <= 0) result += RAND_m;
  return result;
}
#define BSize 0x100
#define BM 0xff
#define PerlinN 0x1000
#define NP 12 /* 2^PerlinN */
#define NM 0xfff
static int uLatticeSelector[BSize + BSize + 2];
static double fGradient[4][BSize + BSize + 2][2];
struct StitchInfo
{
  int nWidth; // How much to subtract to wrap for stitching.
  int nHeight;
  int nWrapX; // Minimum value to wrap.
  int nWrapY;
};
static void init(long lSeed)
{
  double s;
  int i, j, k;
  lSeed = setup_seed(lSeed);
  for(k = 0; k < 4; k++)
  {
    for(i = 0; i < BSize; i++)
    {
      uLatticeSelector[i] = i;
      do {
         for (j = 0; j < 2; j++)
           fGradient[k][i][j] = (double)(((lSeed = random(lSeed)) % (BSize + BSize)) - BSize) / BSize;
      } while(fGradient[k][i][0] == 0 && fGradient[k][i][1] == 0);
      s = double(sqrt(fGradient[k][i][0] * fGradient[k][i][0] + fGradient[k][i][1] * fGradient[k][i][1]));
      fGradient[k][i][0] /= s;
      fGradient[k][i][1] /= s;
    }
  }
  while(--i)
  {
    k = uLatticeSelector[i];
    uLatticeSelector[i] = uLatticeSelector[j = (lSeed = random(lSeed)) % BSize];
    uLatticeSelector[j] = k;
  }
  for(i = 0; i < BSize + 2; i++)
  {
    uLatticeSelector[BSize + i] = uLatticeSelector[i];
    for(k = 0; k < 4; k++)
      for(j = 0; j < 2; j++)
        fGradient[k][BSize + i][j] = fGradient[k][i][j];
  }
}
#define s_curve(t) ( t * t * (3. - 2. * t) )
#define lerp(t, a, b) ( a + t * (b - a) )
double noise2(int nColorChannel, double vec[2], StitchInfo *pStitchInfo)
{
  int bx0, bx1, by0, by1, b00, b10, b01, b11;
  double rx0, rx1, ry0, ry1, *q, sx, sy, a, b, t, u, v;
  int i, j;
  t = vec[0] + PerlinN;
  bx0 = (int)t;
  bx1 = bx0+1;
  rx0 = t - (int)t;
  rx1 = rx0 - 1.0f;
  t = vec[1] + PerlinN;
  by0 = (int)t;
  by1 = by0+1;
  ry0 = t - (int)t;
  ry1 = ry0 - 1.0f;
  // If stitching, adjust lattice points accordingly.
  if(pStitchInfo != NULL)
  {
    if(bx0 >= pStitchInfo->nWrapX)
      bx0 -= pStitchInfo->nWidth;
    if(bx1 >= pStitchInfo->nWrapX)
      bx1 -= pStitchInfo->nWidth;
    if(by0 >= pStitchInfo->nWrapY)
      by0 -= pStitchInfo->nHeight;
    if(by1 >= pStitchInfo->nWrapY)
      by1 -= pStitchInfo->nHeight;
  }
  bx0 &= BM;
  bx1 &= BM;
  by0 &= BM;
  by1 &= BM;
  i = uLatticeSelector[bx0];
  j = uLatticeSelector[bx1];
  b00 = uLatticeSelector[i + by0];
  b10 = uLatticeSelector[j + by0];
  b01 = uLatticeSelector[i + by1];
  b11 = uLatticeSelector[j + by1];
  sx = double(s_curve(rx0));
  sy = double(s_curve(ry0));
  q = fGradient[nColorChannel][b00]; u = rx0 * q[0] + ry0 * q[1];
  q = fGradient[nColorChannel][b10]; v = rx1 * q[0] + ry0 * q[1];
  a = lerp(sx, u, v);
  q = fGradient[nColorChannel][b01]; u = rx0 * q[0] + ry1 * q[1];
  q = fGradient[nColorChannel][b11]; v = rx1 * q[0] + ry1 * q[1];
  b = lerp(sx, u, v);
  return lerp(sy, a, b);
}
double turbulence(int nColorChannel, double *point, double fBaseFreqX, double fBaseFreqY,
          int nNumOctaves, bool bFractalSum, bool bDoStitching,
          double fTileX, double fTileY, double fTileWidth, double fTileHeight)
{
  StitchInfo stitch;
  StitchInfo *pStitchInfo = NULL; // Not stitching when NULL.
  // Adjust the base frequencies if necessary for stitching.
  if(bDoStitching)
  {
    // When stitching tiled turbulence, the frequencies must be adjusted
    // so that the tile borders will be continuous.
    if(fBaseFreqX != 0.0)
    {
      double fLoFreq = double(floor(fTileWidth * fBaseFreqX)) / fTileWidth;
      double fHiFreq = double(ceil(fTileWidth * fBaseFreqX)) / fTileWidth;
      if(fBaseFreqX / fLoFreq < fHiFreq / fBaseFreqX)
        fBaseFreqX = fLoFreq;
      else
        fBaseFreqX = fHiFreq;
    }
    if(fBaseFreqY != 0.0)
    {
      double fLoFreq = double(floor(fTileHeight * fBaseFreqY)) / fTileHeight;
      double fHiFreq = double(ceil(fTileHeight * fBaseFreqY)) / fTileHeight;
      if(fBaseFreqY / fLoFreq < fHiFreq / fBaseFreqY)
        fBaseFreqY = fLoFreq;
      else
        fBaseFreqY = fHiFreq;
    }
    // Set up initial stitch values.
    pStitchInfo = &stitch;
    stitch.nWidth = int(fTileWidth * fBaseFreqX + 0.5f);
    stitch.nWrapX = fTileX * fBaseFreqX + PerlinN + stitch.nWidth;
    stitch.nHeight = int(fTileHeight * fBaseFreqY + 0.5f);
    stitch.nWrapY = fTileY * fBaseFreqY + PerlinN + stitch.nHeight;
  }
  double fSum = 0.0f;
  double vec[2];
  vec[0] = point[0] * fBaseFreqX;
  vec[1] = point[1] * fBaseFreqY;
  double ratio = 1;
  for(int nOctave = 0; nOctave < nNumOctaves; nOctave++)
  {
    if(bFractalSum)
      fSum += double(noise2(nColorChannel, vec, pStitchInfo) / ratio);
    else
      fSum += double(fabs(noise2(nColorChannel, vec, pStitchInfo)) / ratio);
    vec[0] *= 2;
    vec[1] *= 2;
    ratio *= 2;
    if(pStitchInfo != NULL)
    {
      // Update stitch values. Subtracting PerlinN before the multiplication and
      // adding it afterward simplifies to subtracting it once.
      stitch.nWidth *= 2;
      stitch.nWrapX = 2 * stitch.nWrapX - PerlinN;
      stitch.nHeight *= 2;
      stitch.nWrapY = 2 * stitch.nWrapY - PerlinN;
    }
  }
  return fSum;
}

// clang-format on

#undef RAND_m
#undef RAND_a
#undef RAND_q
#undef RAND_r
#undef BSize
#undef BM
#undef PerlinN
#undef NP
#undef NM
#undef s_curve
#undef lerp

} // namespace spec
} // namespace
// ---------------------------------------------------------------------------

namespace casteljau {
namespace {

const PixelRect kBox{100, -40, 164, 24}; // 64 x 64, off the origin

// The pixel the spec's code gives at window (x, y): the spec's conversion
// ((sum + 1) / 2 or sum, clamped to [0, 1]), then premultiplied in float.
Premul reference(const Turbulence& t, const Affine& m, const Rect& tile, int x, int y) {
    const Point p = m * Point{double(kBox.x0 + x), double(kBox.y0 + y)};
    double point[2] = {p.x, p.y};
    float c[4];
    for (int k = 0; k < 4; ++k) {
        const double sum =
            spec::turbulence(k, point, t.base_x, t.base_y, t.octaves, t.fractal_noise, t.stitch,
                             tile.x0, tile.y0, tile.width(), tile.height());
        const double v = t.fractal_noise ? (sum + 1) / 2 : sum;
        c[k] = float(std::fmin(std::fmax(v, 0.0), 1.0));
    }
    return {c[0] * c[3], c[1] * c[3], c[2] * c[3], c[3]};
}

FilterImage run(const Turbulence& t, const Affine& m, const Rect& tile, const Subregion& sub) {
    FilterImage out;
    out.reset(kBox, true);
    turbulence(out, sub, t, m, tile);
    return out;
}

TEST(Turbulence, ParkMillerCheckValue) {
    long s = 1;
    for (int i = 0; i < 10000; ++i) s = spec::random(s);
    EXPECT_EQ(s, 1043618065); // the spec's own check of its generator
}

TEST(Turbulence, MatchesTheSpecCodeBitForBit) {
    const Affine maps[] = {Affine{0.5, 0, 0, 0.75, -13.25, 7.5}, Affine::translate({3.5, -2}) *
                                                                     Affine::rotate(0.3) *
                                                                     Affine::scale(1.25, 0.8)};
    const Rect tile{-10.5, 3.25, 60.5, 45.75};
    struct Case {
        double seed, fx, fy;
        int octaves;
    };
    const Case cases[] = {{0, 0.05, 0.05, 1},  {1, 0.1, 0.07, 2},   {-5, 0.013, 0.21, 4},
                          {42.9, 0.3, 0.3, 3}, {12345, 0.02, 0, 5}, {987654321, 0.8, 0.11, 7}};
    const Subregion sub{0, 0, 64, 64};
    for (const Affine& m : maps)
        for (const Case& c : cases)
            for (bool fractal : {false, true})
                for (bool stitch : {false, true}) {
                    const Turbulence t{c.fx, c.fy, c.octaves, c.seed, fractal, stitch};
                    spec::init(long(std::trunc(c.seed)));
                    const FilterImage out = run(t, m, tile, sub);
                    std::set<float> alphas;
                    for (int y = 0; y < 64; ++y)
                        for (int x = 0; x < 64; ++x) {
                            const Premul want = reference(t, m, tile, x, y);
                            const Premul got = out.at(x, y);
                            alphas.insert(got.a);
                            ASSERT_TRUE(got.r == want.r && got.g == want.g && got.b == want.b &&
                                        got.a == want.a)
                                << "seed " << c.seed << " freq " << c.fx << "," << c.fy
                                << " octaves " << c.octaves << " fractal " << fractal << " stitch "
                                << stitch << " at " << x << "," << y << ": got " << got.r << ","
                                << got.g << "," << got.b << "," << got.a << " want " << want.r
                                << "," << want.g << "," << want.b << "," << want.a;
                        }
                    // The comparison means something: the noise varies.
                    EXPECT_GT(alphas.size(), 50u) << "seed " << c.seed << " fractal " << fractal;
                }
}

TEST(Turbulence, WritesOnlyTheSubregion) {
    const Turbulence t{0.05, 0.05, 3, 7, true, false};
    const Affine m = Affine::scale(0.5);
    const Rect tile{0, 0, 100, 100};
    const Subregion sub{5, 9, 40, 33};
    spec::init(7);
    const FilterImage out = run(t, m, tile, sub);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Premul want = sub.contains(x, y) ? reference(t, m, tile, x, y) : Premul{};
            const Premul got = out.at(x, y);
            ASSERT_TRUE(got.r == want.r && got.g == want.g && got.b == want.b && got.a == want.a)
                << x << "," << y;
        }
}

TEST(Turbulence, NoOctavesIsTransparent) {
    for (int octaves : {0, -3})
        for (bool fractal : {false, true}) {
            const Turbulence t{0.05, 0.05, octaves, 0, fractal, false};
            const FilterImage out = run(t, Affine{}, Rect{0, 0, 64, 64}, {0, 0, 64, 64});
            for (const Premul& p : out.px)
                ASSERT_TRUE(p.r == 0 && p.g == 0 && p.b == 0 && p.a == 0);
        }
}

// The seed is truncated towards zero: 7.9 is 7 and -7.9 is -7, not -8.
TEST(Turbulence, SeedIsTruncated) {
    const Affine m = Affine::scale(0.7);
    const Rect tile{0, 0, 64, 64};
    auto same_image = [&](double s1, double s2) {
        const FilterImage a = run({0.07, 0.07, 2, s1, false, false}, m, tile, {0, 0, 64, 64});
        const FilterImage b = run({0.07, 0.07, 2, s2, false, false}, m, tile, {0, 0, 64, 64});
        for (std::size_t i = 0; i < a.px.size(); ++i)
            if (a.px[i].a != b.px[i].a || a.px[i].r != b.px[i].r) return false;
        return true;
    };
    EXPECT_TRUE(same_image(7.9, 7));
    EXPECT_TRUE(same_image(-7.9, -7));
    EXPECT_FALSE(same_image(-7.9, -8));
    EXPECT_FALSE(same_image(7.9, 8));
}

} // namespace
} // namespace casteljau
