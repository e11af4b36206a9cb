// Seeded curve generators shared by the tests and the benchmarks, so both
// measure the same corpus. Sizes are in device pixels.
#pragma once

#include "casteljau/curve/bez.h"
#include "casteljau/curve/bezier.h"
#include "casteljau/curve/conic.h"
#include "casteljau/curve/path.h"

#include <random>
#include <string>
#include <vector>

namespace casteljau::testing {

class Rng {
  public:
    explicit Rng(unsigned seed) : gen_(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(gen_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<>(lo, hi)(gen_); }
    Point point(double extent) { return {uniform(0, extent), uniform(0, extent)}; }
    // Log-uniform: sizes and tolerances spread over orders of magnitude.
    double log_uniform(double lo, double hi);

  private:
    std::mt19937_64 gen_;
};

struct NamedCubic {
    std::string kind;
    CubicBez curve;
};

// The benchmark corpus of the foundation issue: random cubics, quarter circles,
// S-curves, loops, near-cusps and long nearly straight curves, `per_kind` of
// each, at sizes of 50 to 800 px.
std::vector<NamedCubic> cubic_corpus(unsigned seed, int per_kind);

QuadBez random_quad(Rng& rng, double extent);
CubicBez random_cubic(Rng& rng, double extent);
Conic random_conic(Rng& rng, double extent);
// A closed chain of `segments` random lines, quadratics, cubics and conics
// through points of an extent x extent box.
Path random_blob(Rng& rng, double extent, int segments);
Bezier random_bezier(Rng& rng, int degree, double extent);

// Integral of sqrt(kappa / (8 tol)) ds over the curve: the segment count of an
// optimal polyline with vertices on the curve (Levien 2019), by adaptive Simpson.
double optimal_segments(const CubicBez& c, double tolerance);

} // namespace casteljau::testing
