// The flatteners against each other and uniform sampling at equal measured error.
//
// Corpus: testing::cubic_corpus (random cubics, quarter circles, S-curves,
// loops, near-cusps, long nearly straight curves; seeded), also used by the
// tests. For each tolerance and method one benchmark flattens the whole corpus
// per iteration; counters:
//   ns_per_curve        time per curve (the benchmark's time / curves)
//   segments_per_curve  mean segments emitted per curve
//   Msegments_per_s     emitted segments per second
//   max_error_px        the measured maximum error (error.h), taken once
//   vs_optimal          segments / the optimal count (integral of sqrt(k / 8 tol) ds)
//   asked_px            the tolerance the method was asked for
// Methods: integral (evenly spaced in the integral of the
// segment density, every chord checked, integral.h), adaptive (adaptive.h),
// halving (textbook, halving.h), guided (cut into the predicted number of
// pieces, guided.h), uniform_best (per curve the smallest N whose measured
// error meets the tolerance: the strongest uniform baseline, its N found
// before timing), uniform_wang (N from Wang's bound, computed inside the
// timed loop, as a renderer would), levien (Levien's method, levien.h, asked
// for the tolerance: its measured error goes past it) and levien_equal (the
// same, asked for the tolerance at which its measured error meets the target).
#include "casteljau/flatten/error.h"
#include "casteljau/flatten/flatten.h"
#include "casteljau/flatten/levien.h"
#include "corpus.h"

#include <benchmark/benchmark.h>
#include <string>
#include <type_traits>
#include <vector>

namespace casteljau {
namespace {

const std::vector<testing::NamedCubic>& corpus() {
    static const auto c = testing::cubic_corpus(2026, 50);
    return c;
}

enum class Method {
    Adaptive,
    Halving,
    Guided,
    UniformBest,
    UniformWang,
    Integral,
    Levien,
    LevienEqual
};
const char* const kNames[] = {"adaptive",     "halving",  "guided", "uniform_best",
                              "uniform_wang", "integral", "levien", "levien_equal"};
const double kTolerances[] = {1.0, 0.5, 0.25, 0.1};

struct Prepared {
    std::vector<int> best_n; // UniformBest only
    double tol = 0;          // the tolerance asked of the method: LevienEqual's is lower
    double segments = 0, max_error = 0, optimal = 0;
};

template <Method M, class Sink>
void flatten_with(const CubicBez& c, double tol, int best_n, Sink&& sink) {
    if constexpr (M == Method::Adaptive)
        flatten_adaptive(c, tol, sink);
    else if constexpr (M == Method::Halving)
        flatten_halving(c, tol, sink);
    else if constexpr (M == Method::Guided)
        flatten_guided(c, tol, sink);
    else if constexpr (M == Method::UniformBest)
        flatten_uniform(c, best_n, sink);
    else if constexpr (M == Method::UniformWang)
        flatten_uniform(c, wang_segments(c, tol), sink);
    else if constexpr (M == Method::Integral)
        flatten_integral(c, tol, sink);
    else
        flatten_levien(c, tol, sink);
}

// f(std::integral_constant<Method, m>): the method chosen once, outside the
// loops, which are then compiled for it alone (corpus_pass).
template <class F>
void with_method(Method m, F&& f) {
    using M = Method;
    switch (m) {
    case M::Adaptive:
        return f(std::integral_constant<M, M::Adaptive>{});
    case M::Halving:
        return f(std::integral_constant<M, M::Halving>{});
    case M::Guided:
        return f(std::integral_constant<M, M::Guided>{});
    case M::UniformBest:
        return f(std::integral_constant<M, M::UniformBest>{});
    case M::UniformWang:
        return f(std::integral_constant<M, M::UniformWang>{});
    case M::Integral:
        return f(std::integral_constant<M, M::Integral>{});
    case M::Levien:
    case M::LevienEqual:
        return f(std::integral_constant<M, M::Levien>{});
    }
}

template <class Sink>
void flatten_one(const CubicBez& c, Method m, double tol, int best_n, Sink&& sink) {
    with_method(m, [&](auto method) { flatten_with<method()>(c, tol, best_n, sink); });
}

// The method's counts and measured error on the corpus at tolerance `asked`.
Prepared measure(Method m, double tol, double asked) {
    Prepared p;
    p.tol = asked;
    for (const auto& [kind, c] : corpus()) {
        const int n =
            m == Method::UniformBest ? best_uniform_segments(c, tol, wang_segments(c, tol)) : 0;
        p.best_n.push_back(n);
        std::vector<FlatVertex> v;
        flatten_one(c, m, asked, n, [&](const FlatVertex& x) { v.push_back(x); });
        p.segments += double(v.size());
        p.max_error = std::max(p.max_error, polyline_error(c, c.start(), v));
        p.optimal += testing::optimal_segments(c, tol);
    }
    return p;
}

// LevienEqual: Levien's flattener asked for the largest tolerance (to 0.1%,
// by bisection) at which its measured error on the corpus meets `tol`, so that
// it is compared at equal measured error; the others are asked for `tol`.
Prepared prepare(Method m, double tol) {
    if (m != Method::LevienEqual) return measure(m, tol, tol);
    double lo = 0.05, hi = 1.0; // fractions of tol: lo meets it
    while (hi - lo > 1e-3) {
        const double mid = 0.5 * (lo + hi);
        (measure(m, tol, mid * tol).max_error <= tol ? lo : hi) = mid;
    }
    return measure(m, tol, lo * tol);
}

// One timed pass over the corpus, a function of its own for each method: with
// every method's loop in BM_Flatten's body, guided measured 0.44 us a curve
// against 0.36. (The integral flattener's 0.98 against 0.73 was its helpers
// left out of line, integral.h.)
template <Method M>
[[gnu::noinline]] double corpus_pass(const std::vector<testing::NamedCubic>& curves,
                                     const Prepared& p) {
    double checksum = 0;
    for (std::size_t i = 0; i < curves.size(); ++i)
        flatten_with<M>(curves[i].curve, p.tol, p.best_n[i],
                        [&](const FlatVertex& v) { checksum += v.p.x; });
    return checksum;
}

void BM_Flatten(benchmark::State& state, Method m, double tol) {
    const Prepared p = prepare(m, tol);
    const auto& curves = corpus();
    with_method(m, [&](auto method) {
        for (auto _ : state) benchmark::DoNotOptimize(corpus_pass<method()>(curves, p));
    });
    const double n = double(curves.size());
    using C = benchmark::Counter;
    state.counters["ns_per_curve"] = C(n * 1e-9, C::kIsIterationInvariantRate | C::kInvert);
    state.counters["segments_per_curve"] = p.segments / n;
    state.counters["Msegments_per_s"] = C(p.segments * 1e-6, C::kIsIterationInvariantRate);
    state.counters["max_error_px"] = p.max_error;
    state.counters["vs_optimal"] = p.segments / p.optimal;
    state.counters["asked_px"] = p.tol;
}

// Per-kind view at the default tolerance: where adaptive wins, and by how much.
void BM_FlattenKind(benchmark::State& state, Method m, std::string kind) {
    std::vector<CubicBez> curves;
    for (const auto& [k, c] : corpus())
        if (k == kind) curves.push_back(c);
    const double tol = 0.25;
    std::vector<int> best_n;
    double segments = 0;
    for (const CubicBez& c : curves) {
        best_n.push_back(best_uniform_segments(c, tol, wang_segments(c, tol)));
        flatten_one(c, m, tol, best_n.back(), [&](const FlatVertex&) { segments += 1; });
    }
    with_method(m, [&](auto method) {
        for (auto _ : state) {
            double checksum = 0;
            for (std::size_t i = 0; i < curves.size(); ++i)
                flatten_with<method()>(curves[i], tol, best_n[i],
                                       [&](const FlatVertex& v) { checksum += v.p.y; });
            benchmark::DoNotOptimize(checksum);
        }
    });
    using C = benchmark::Counter;
    state.counters["ns_per_curve"] =
        C(double(curves.size()) * 1e-9, C::kIsIterationInvariantRate | C::kInvert);
    state.counters["segments_per_curve"] = segments / double(curves.size());
}

// Conics (circular arcs of 20 to 90 degrees, radius 5 to 400 px, as arcs of
// SVG paths and the o's of text become) by the guided flattener: its
// homogeneous Hermite pieces (ConicPieces, the default) against de
// Casteljau subsegments measured by hull_deviation (the reference), at 0.25 px.
template <class Pieces>
void BM_FlattenConics(benchmark::State& state, double radius) {
    testing::Rng rng(2026);
    std::vector<HConic> arcs;
    for (int i = 0; i < 1000; ++i) {
        const double start = rng.uniform(0, 6.3), sweep = rng.uniform(0.35, 1.57);
        arcs.push_back(HConic::from(Conic::circular_arc(
            rng.point(500), radius * rng.uniform(0.5, 1.5), start, start + sweep)));
    }
    double segments = 0;
    for (auto _ : state) {
        double checksum = 0;
        for (const HConic& c : arcs)
            for (const FlatVertex& v : GuidedFlattener<HConic, Pieces>(c, 0.25)) {
                checksum += v.p.x;
                segments += 1;
            }
        benchmark::DoNotOptimize(checksum);
    }
    using C = benchmark::Counter;
    state.counters["ns_per_curve"] =
        C(double(arcs.size()) * 1e-9, C::kIsIterationInvariantRate | C::kInvert);
    state.counters["segments_per_curve"] = segments / double(state.iterations() * arcs.size());
    state.counters["Msegments_per_s"] = C(segments * 1e-6, C::kIsRate);
}

const int kRegistered = [] {
    for (double tol : kTolerances)
        for (Method m : {Method::Integral, Method::Adaptive, Method::Guided, Method::UniformBest,
                         Method::UniformWang, Method::Halving, Method::Levien, Method::LevienEqual})
            benchmark::RegisterBenchmark(("flatten/" + std::string(kNames[int(m)]) +
                                          "/tol:" + std::to_string(tol).substr(0, 4))
                                             .c_str(),
                                         BM_Flatten, m, tol);
    for (const char* kind :
         {"random", "quarter_circle", "s_curve", "loop", "near_cusp", "nearly_straight"})
        for (Method m : {Method::Integral, Method::Adaptive, Method::Guided, Method::UniformBest,
                         Method::Levien})
            benchmark::RegisterBenchmark(
                ("kind/" + std::string(kind) + "/" + kNames[int(m)]).c_str(), BM_FlattenKind, m,
                std::string(kind));
    for (double r : {5.0, 20.0, 100.0, 400.0}) {
        const std::string radius = "/r:" + std::to_string(int(r));
        benchmark::RegisterBenchmark(("conic/guided" + radius).c_str(),
                                     BM_FlattenConics<ConicPieces>, r);
        benchmark::RegisterBenchmark(("conic/guided_subsegment" + radius).c_str(),
                                     BM_FlattenConics<SubsegmentPieces<HConic>>, r);
    }
    return 0;
}();

} // namespace
} // namespace casteljau

BENCHMARK_MAIN();
