#include "casteljau/stroke/stroker.h"

#include "casteljau/flatten/flatten.h"
#include "casteljau/geom/fixed_stack.h"
#include "casteljau/stroke/detail/inner_join.h"
#include "casteljau/stroke/detail/pieces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <span>
#include <type_traits>

namespace casteljau {

namespace {

constexpr double kPi = std::numbers::pi;

using stroke_detail::Growth;
using stroke_detail::kMeetEdges;
using stroke_detail::Neighbours;
using stroke_detail::Pieces;
using stroke_detail::Sample;

// All control points coincide: the segment is a point.
bool degenerate(const Segment& s) {
    const Rect b = segment_control_bounds(s);
    return b.width() == 0 && b.height() == 0;
}

// Unit tangent at t of c, the curve of segment s, with the limit direction
// where the derivative vanishes. Typed: it runs for every sample.
template <class Curve>
Vec2 tangent(const Segment& s, const Curve& c, double t) {
    if (t <= 0) return segment_start_tangent(s).normalized();
    if (t >= 1) return segment_end_tangent(s).normalized();
    const Vec2 d = c.deriv(t);
    if (d.length_sq() > 1e-24 * (1 + c.start().to_vec().length_sq())) return d.normalized();
    return c.deriv(std::min(1.0, t + 1e-7)).normalized();
}

// Points on one round join or cap at most, and so the least normal turn
// between samples is pi / kMaxArcSteps (below). Only strokes wider than
// about 1.4e7 tolerances reach it (3.5e6 px at 0.25 px): their arcs are then
// coarser than the tolerance, by 7.4e-8 of the half-width.
constexpr double kMaxArcSteps = 1 << 12;

// Outline points per call (a strip of rows, see Renderer) at most: a subpath
// that would take more is not drawn, nor any after it. Counted as a subpath
// grows, since one subpath alone can hold millions (round joins on a stroke
// 1e6 px wide: 4400 points each). A point costs some 70 bytes on its way to
// coverage (itself, its edge, its sorted edge, vectors' slack), so 2^23
// stay within the 1 GiB promised for hostile input, at twice the 3.6M of the
// million-segment zigzag of tests/bad_input, all in one strip.
constexpr std::size_t kMaxOutlinePoints = std::size_t(1) << 23;

// (b): the normal may turn by dphi between samples; at least 4 samples per
// quarter turn keep round joins and tiny widths sensible too. dphi =
// 2 acos(1 - x), x = tol / 2h, is computed as 4 asin(sqrt(x / 2)), the same
// angle, which stays positive when x is below the rounding of 1 - x (a
// stroke 1e22 px wide gave 0: infinitely many samples and arc points).
double max_normal_turn(double h, double tol) {
    const double x = std::min(tol / (2.0 * h), 2.0);
    return std::clamp(4.0 * std::asin(std::sqrt(x / 2.0)), kPi / kMaxArcSteps, kPi / 8);
}

// The tolerance left for (a) once (b) has taken h (1 - cos(dphi/2)) =
// 2 h sin^2(dphi/4) (written without the cancellation of 1 - cos): tol / 2
// when dphi comes from the tolerance, more when the cap of pi/8 on dphi
// leaves (b) less (a 1 px stroke at 0.25 px: 0.24 px instead of 0.125, so
// about 1/sqrt(1.9) = 0.72x the samples on its curves).
double base_tolerance(double h, double tol, double dphi) {
    const double s = std::sin(dphi / 4);
    return tol - std::min(tol / 2, 2 * h * s * s);
}

// Lengths below kUnresolved tolerances (1/256 px at the default 0.25 px)
// are below what the offsets resolve: a chord that short ends the bisection
// for (b), which rounds the normal's turn there as a cusp, and a handle that
// short is collapsed onto its end point (stroker.h: the end-tangent rule),
// as it only steers the normal over a chord about as short.
constexpr double kUnresolved = 1.0 / 64;

// Moves onto p[0] the control points after it that lie within eps of it, and
// onto p[n] those before it likewise: the end points stay, and the curve moves
// by at most eps (a polynomial or positive-weight rational curve is a convex
// combination of its control points, and the moved ones' weights sum to at
// most 1). False, and p unchanged, when no point moves or the curve would
// collapse to a point.
bool collapse_polygon_handles(std::span<Point> p, double eps) {
    const std::size_t n = p.size() - 1;
    const double eps_sq = eps * eps;
    std::size_t i = 1, j = n - 1; // p[1, i) move to p[0], p(j, n - 1] to p[n]
    while (i < n && (p[i] - p[0]).length_sq() < eps_sq) ++i;
    while (j >= i && j > 0 && (p[j] - p[n]).length_sq() < eps_sq) --j;
    if (i == 1 && j == n - 1) return false;
    if (p[0] == p[n] && j < i) return false; // every point within eps of p[0]
    for (std::size_t k = 1; k < i; ++k) p[k] = p[0];
    for (std::size_t k = j + 1; k < n; ++k) p[k] = p[n];
    return true;
}

// The segment with its short handles collapsed (collapse_polygon_handles); false
// when none is. Conics of weight <= 0 are not convex combinations of their
// control points and are left as they are.
bool collapse_short_handles(const Segment& s, double eps, Segment& out) {
    return std::visit(
        [&](const auto& c) {
            using Curve = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<Curve, Line>) {
                return false;
            } else if constexpr (std::is_same_v<Curve, Conic>) {
                std::array<Point, 3> p = c.control_points();
                if (!(c.w > 0) || !collapse_polygon_handles(p, eps)) return false;
                out = Conic{p[0], p[1], p[2], c.w};
                return true;
            } else {
                Curve r = c;
                if (!collapse_polygon_handles(r.p, eps)) return false;
                out = r;
                return true;
            }
        },
        s);
}

// (b) inside a piece of c over [t0, t1] whose end tangents d0 and d1 (unit)
// are within dphi (given as its cosine): whether every tangent between is.
// The derivative of the piece is a Bezier whose control vectors are, up to
// the factor t1 - t0, the blossoms of c's hodograph H at (t0, ..., t1), so
// every tangent of the piece lies in their cone, and the first and last of
// them point along d0 and d1. For lines, quadratics and positive-weight
// conics (whose pieces' control polygons have two legs, along the end
// tangents) that is all. A cubic's piece has a middle one, H(t0, t1), which
// must lie within dphi of both ends: directions pairwise within an angle
// below pi/2 (dphi <= pi/8) lie in an arc of that angle. The ends alone do
// not do: on M30 150 C 30.0001 150 150 30 150.0001 30 (issue 21) both end
// tangents are +x and the one in between diagonal, and the two end samples
// drew a parallelogram 0.7x as wide as the stroke.
template <class Curve>
struct Interior {
    explicit Interior(const Curve&) {}
    bool turns_within(double, double, Vec2, Vec2, double) const { return true; }
};

template <>
struct Interior<CubicBez> {
    // H(t0, t1) = a + b (t0 + t1) + c t0 t1, from the hodograph H0, H1, H2.
    Vec2 a, b, c;
    explicit Interior(const CubicBez& cubic) {
        const auto h = cubic.hodograph();
        a = h[0], b = h[1] - h[0], c = h[0] - h[1] * 2.0 + h[2];
    }
    bool turns_within(double t0, double t1, Vec2 d0, Vec2 d1, double cos_dphi) const {
        const Vec2 m = a + b * (t0 + t1) + c * (t0 * t1);
        // m is within dphi (< pi/2) of the unit d when m.d >= cos(dphi) |m|:
        // squared, no root. Asked as "is it outside", so that a NaN from
        // overflowing geometry counts as within, as it did at the ends.
        const double a0 = m.dot(d0), a1 = m.dot(d1), c2 = cos_dphi * cos_dphi * m.length_sq();
        return !(a0 < 0 || a0 * a0 < c2 || a1 < 0 || a1 * a1 < c2);
    }
};

class Sampler {
  public:
    // dphi = max_normal_turn(h, tol).
    Sampler(double h, double tol, double dphi, std::vector<FlatVertex>& vertices, Growth& growth)
        : tol_(tol), base_tol_(base_tolerance(h, tol, dphi)), cos_dphi_(std::cos(dphi)),
          vertices_(vertices), growth_(growth) {}

    // Samples of one segment, t = 0 first, and of its end tangents (the first
    // and last samples'), with handles shorter than kUnresolved tolerances
    // collapsed: (a) is then held to that much less, so that the samples stay
    // within tol of the offsets of a curve within tol / 64 of the given one.
    // False, with `out` unfinished, when they would be more than `limit`:
    // the caller drops the subpath, and the buffers never outgrow what it
    // would accept (a flattening alone can be 2^24 vertices).
    bool run(const Segment& s, std::vector<Sample>& out, std::size_t limit) {
        Segment collapsed;
        const double eps = kUnresolved * tol_;
        const bool moved = collapse_short_handles(s, eps, collapsed);
        const Segment& seg = moved ? collapsed : s;
        return std::visit(
            [&](const auto& c) { return run(seg, c, base_tol_ - (moved ? eps : 0.0), out, limit); },
            seg);
    }

  private:
    template <class Curve>
    bool run(const Segment& s, const Curve& c, double base_tol, std::vector<Sample>& out,
             std::size_t limit) {
        Vec2 d = tangent(s, c, 0.0);
        out.push_back({c.start(), d});
        // (a): the guided flattener's vertices at the base tolerance (cheaper
        // per sample than adaptive's exact chords; measured faster on thin
        // strokes in bench/render/cairo_compare_bench, where (a) dominates).
        // Each vertex is a sample: past `limit` the rest are not kept.
        vertices_.clear();
        flatten_curve(c, FlattenOptions{base_tol, FlattenMethod::Guided, 0},
                      [&](const FlatVertex& v) {
                          if (growth_.may_grow(vertices_.size(), limit)) vertices_.push_back(v);
                      });
        if (vertices_.size() >= limit) return false;
        FlatVertex a{c.start(), 0.0};
        const Interior<Curve> interior(c);
        for (const FlatVertex& b : vertices_) {
            if (!refine(s, c, interior, a, b, d, out, limit)) return false;
            a = b;
        }
        return true;
    }

    // (b) between the curve points a and b, by bisection to depth 16; `d` is
    // the unit tangent at a on entry, at b on return. The left half is worked
    // on at once and only right halves wait on the stack (one per depth), so
    // the usual span, which needs no cut, touches no stack. False when `out`
    // reaches `limit` samples first.
    template <class Curve>
    bool refine(const Segment& s, const Curve& c, const Interior<Curve>& interior, FlatVertex a,
                FlatVertex b, Vec2& d, std::vector<Sample>& out, std::size_t limit) {
        struct Span {
            FlatVertex a, b;
            int depth;
        };
        FixedStack<Span, 16> right_halves; // runs once per flattened vertex
        Span sp{a, b, 0};
        for (;;) {
            const Vec2 db = tangent(s, c, sp.b.t);
            // The unit tangents turn by more than dphi in [0, pi] exactly when
            // their dot product is below cos(dphi): no angle needs computing.
            // Between them, the control polygon of the piece decides.
            const bool turns =
                d.dot(db) < cos_dphi_ || !interior.turns_within(sp.a.t, sp.b.t, d, db, cos_dphi_);
            if (turns && sp.depth < 16 && distance(sp.a.p, sp.b.p) > kUnresolved * tol_) {
                const double m = 0.5 * (sp.a.t + sp.b.t);
                const FlatVertex mid{c.eval(m), m};
                right_halves.push({mid, sp.b, sp.depth + 1});
                sp = {sp.a, mid, sp.depth + 1};
                continue;
            }
            if (!growth_.may_grow(out.size(), limit)) return false;
            out.push_back({sp.b.p, db, turns});
            d = db;
            if (right_halves.empty()) return true;
            sp = right_halves.pop();
        }
    }

    double tol_, base_tol_, cos_dphi_;
    std::vector<FlatVertex>& vertices_; // the flattener's, a buffer kept between strokes
    Growth& growth_;
};

} // namespace

// Everything a stroke is built in, kept between strokes: once the buffers
// have grown, outlining allocates nothing.
struct Stroker::Buffers {
    Growth growth; // the call's
    Pieces pieces;
    std::vector<const Segment*> segs;
    std::vector<FlatVertex> vertices;
    std::vector<Sample> samples, before; // a segment's, the one before it's
    std::vector<Sample> head;            // the first ones of a closed subpath's first segment
    std::vector<Point> right;
    stroke_detail::DashBuffers dash;
    std::vector<Polygon> polygons; // [0, count) are the last outline's
    std::size_t count = 0;

    // A cleared polygon for the outline, reusing an old one's storage.
    // Invalidates references to earlier ones.
    std::size_t new_polygon() {
        if (count == polygons.size()) polygons.emplace_back();
        polygons[count].clear();
        return count++;
    }

    // Frees every buffer but the first `keep` polygons of the outline, and
    // gives back the reservation. (A vector assigned {} keeps its storage:
    // the initializer-list overload.)
    void release(std::size_t keep) {
        growth.give_back();
        polygons.resize(keep);
        polygons.shrink_to_fit();
        Buffers kept;
        kept.growth = growth;
        kept.polygons = std::move(polygons);
        kept.count = keep;
        *this = std::move(kept);
    }
};

namespace {

// One side of the outline, or a cap or join, is built on a point list.
class Outline {
  public:
    Outline(double h, double tol, const StrokeGeometry& st, Stroker::Buffers& b)
        : h_(h), tol_(tol), dphi_(max_normal_turn(h, tol)), st_(st), b_(b),
          sampler_(h, tol, dphi_, b.vertices, b.growth) {}

    // Arc of radius h around c from direction u0 to u1, turning `sweep` radians
    // (signed), endpoints excluded.
    void arc(std::vector<Point>& out, Point c, Vec2 u0, double sweep) const {
        const int n = int(std::clamp(std::ceil(std::fabs(sweep) / dphi_), 1.0, kMaxArcSteps));
        const double a0 = std::atan2(u0.y, u0.x);
        for (int i = 1; i < n; ++i) {
            const double a = a0 + sweep * i / n;
            out.push_back(c + Vec2{std::cos(a), std::sin(a)} * h_);
        }
    }

    // Join at p from tangent d0 to d1. `side` +1 builds the left side (p + h n), -1 the right.
    // True when this is the inner side: then it went through the joint,
    // whose loop meet() may cut out once the offsets after it are built.
    bool join(std::vector<Point>& out, Point p, Vec2 d0, Vec2 d1, int side, LineJoin how) const {
        const Vec2 n0 = d0.perp() * double(side), n1 = d1.perp() * double(side);
        const double turn = d0.cross(d1) * side; // > 0: this side is the inner one
        if (std::fabs(d0.cross(d1)) < 1e-12 && d0.dot(d1) > 0) return false; // straight on
        if (turn > 0 && d0.dot(d1) > -1 + 1e-12) {
            out.push_back(p);
            return true;
        }
        if (how == LineJoin::Round) {
            const double sweep = std::atan2(n0.cross(n1), n0.dot(n1));
            arc(out, p, n0, std::fabs(d0.cross(d1)) < 1e-12 ? kPi * (side > 0 ? -1 : 1) : sweep);
        } else if (how == LineJoin::Miter) {
            const double c = n0.dot(n1);
            const double ratio =
                1.0 / std::sqrt(std::max(1e-300, (1.0 + c) / 2.0)); // 1 / sin(theta / 2)
            if (ratio <= st_.miter_limit) out.push_back(p + (n0 + n1) * (h_ / (1.0 + c)));
        } // bevel: the straight edge to the next offset point
        return false;
    }

    // Cap at the end point p with unit tangent d (pointing out of the stroke),
    // from the left offset to the right offset.
    void cap(std::vector<Point>& out, Point p, Vec2 d) const {
        const Vec2 n = d.perp();
        if (st_.cap == LineCap::Square) {
            out.push_back(p + n * h_ + d * h_);
            out.push_back(p - n * h_ + d * h_);
        } else if (st_.cap == LineCap::Round) {
            arc(out, p, n, -kPi);
        }
    }

    // A zero-length subpath's caps: a disc, or a square facing `along` (a
    // unit vector, pieces.h's Run::along). Both turn as an open subpath's
    // outline turns (its caps sweep -pi), so that where a dot overlaps a
    // stroke the windings add up, not cancel (a dot at a dash's end cut a
    // hole in its cap).
    void zero_length(Point p, Vec2 along) const {
        if (st_.cap == LineCap::Round) {
            Polygon& disc = b_.polygons[b_.new_polygon()];
            disc.push_back(p + Vec2{h_, 0});
            arc(disc, p, {1, 0}, -2 * kPi);
        } else if (st_.cap == LineCap::Square) {
            Polygon& square = b_.polygons[b_.new_polygon()];
            const Vec2 d = along * h_, n = along.perp() * h_;
            for (const Vec2 v : {-d - n, -d + n, d + n, d - n}) square.push_back(p + v);
        }
    }

    // Outlines a subpath, unless it takes more than `budget` points: then
    // it is dropped (a part of it would be a wrong shape) and false returned.
    // Counted per segment: one adds its samples, which are not made past
    // what could fit, and a few joins.
    bool subpath(Point start, std::span<const Segment> segments, bool closed, Vec2 along,
                 std::size_t budget) {
        std::vector<const Segment*>& segs = b_.segs;
        segs.clear();
        for (const Segment& s : segments)
            if (!degenerate(s)) segs.push_back(&s);
        if (segs.empty()) {
            zero_length(start, along);
            return true;
        }
        // Both sides' polygons are taken before either is referenced: taking
        // one may move the others.
        const std::size_t left_at = b_.new_polygon();
        const std::size_t right_at = closed ? b_.new_polygon() : left_at;
        std::vector<Point>& left = b_.polygons[left_at];
        std::vector<Point>& right = closed ? b_.polygons[right_at] : b_.right;
        right.clear();
        const auto drop = [&] {
            b_.count = left_at;
            return false;
        };
        std::vector<Sample>& samples = b_.samples;
        std::vector<Sample>& before = b_.before;
        std::vector<Sample>& head = b_.head;
        Vec2 first_d{}, last_d{};
        Point last_p{};
        // Per side (left, right): where the last segment's offsets begin and
        // the first one's end, which bound the offsets meet() searches.
        std::vector<Point>* const sides[2] = {&left, &right};
        const int sign[2] = {+1, -1};
        std::size_t begin[2] = {0, 0}, first_end[2] = {0, 0};
        for (std::size_t i = 0; i < segs.size(); ++i) {
            samples.swap(before);
            samples.clear();
            // Each sample adds a point to either side: more than half the
            // budget left cannot fit.
            if (!sampler_.run(*segs[i], samples, (budget - left.size() - right.size()) / 2))
                return drop();
            bool inner[2] = {false, false};
            if (i == 0) first_d = samples[0].d;
            for (int s = 0; s < 2 && i > 0; ++s)
                inner[s] = join(*sides[s], samples[0].p, last_d, samples[0].d, sign[s], st_.join);
            const std::size_t at[2] = {left.size(), right.size()}; // its first offsets
            for (std::size_t k = 0; k < samples.size(); ++k) {
                const Sample& s = samples[k];
                if (s.cusp_before && k > 0) { // a cusp inside the curve: round it
                    join(left, s.p, samples[k - 1].d, s.d, +1, LineJoin::Round);
                    join(right, s.p, samples[k - 1].d, s.d, -1, LineJoin::Round);
                }
                left.push_back(s.p + s.d.perp() * h_);
                right.push_back(s.p - s.d.perp() * h_);
            }
            const Neighbours around{before, samples, h_ + tol_};
            for (int s = 0; s < 2; ++s) {
                begin[s] =
                    inner[s] ? stroke_detail::meet(*sides[s], begin[s], at[s] - 1, around) : at[s];
                if (i == 0) first_end[s] = sides[s]->size();
                if (i == 1) first_end[s] = std::min(first_end[s], begin[s] + 1); // cut at X
            }
            if (i == 0 && closed) { // for meet_closing, once `samples` is another segment's
                const std::size_t n = std::min(samples.size(), kMeetEdges + 1);
                head.assign(samples.begin(), samples.begin() + std::ptrdiff_t(n));
            }
            last_d = samples.back().d;
            last_p = samples.back().p;
            if (left.size() + right.size() > budget) return drop();
            // The call's points: the earlier subpaths' (what the budget lacks) and these.
            b_.growth.reached(kMaxOutlinePoints - budget + left.size() + right.size());
        }
        if (closed) {
            const Neighbours around{samples, head, h_ + tol_};
            for (int s = 0; s < 2; ++s)
                if (join(*sides[s], last_p, last_d, first_d, sign[s], st_.join))
                    stroke_detail::meet_closing(*sides[s], begin[s], first_end[s], around);
            std::reverse(right.begin(), right.end());
            return true;
        }
        cap(left, last_p, last_d);
        left.insert(left.end(), right.rbegin(), right.rend());
        cap(left, start, -first_d);
        return true;
    }

  private:
    double h_, tol_, dphi_;
    const StrokeGeometry& st_;
    Stroker::Buffers& b_;
    Sampler sampler_; // one per stroke: its buffers serve every segment
};

} // namespace

Stroker::Stroker() : b_(std::make_unique<Buffers>()) {}
Stroker::~Stroker() {
    if (b_) b_->growth.give_back();
}
Stroker::Stroker(Stroker&&) noexcept = default;
Stroker& Stroker::operator=(Stroker&& o) noexcept {
    if (this != &o) {
        if (b_) b_->growth.give_back();
        b_ = std::move(o.b_);
    }
    return *this;
}

// The largest coordinate (or length) the outline is built at: squares of
// lengths, which the sampler and the flattener take, stay far below the
// doubles' 1.8e308. A stroke whose kept box or reach is larger (a stroke
// 1e300 wide: its lengths' squares overflowed to infinity, every normal was
// NaN and one line took 65,537 samples, another an unbounded flattening,
// 12.7 GB) is built scaled down by a power of two, exactly, and scaled back.
constexpr double kMaxMagnitude = 1e100;

std::span<const Polygon> Stroker::outline(const Path& path, const StrokeGeometry& style,
                                          double tolerance, const Rect& visible) {
    Buffers& b = *b_;
    b.count = 0;
    b.growth.through = false;
    const double h = style.width / 2;
    // An infinite tolerance asks for no outline: the samplers' steps would
    // be NaN and never reach the curve's end (a hang before).
    if (!(h > 0) || !(tolerance > 0) || !std::isfinite(tolerance)) return {};
    // How far the outline reaches from the path: a miter up to the limit, a
    // square cap's corner at sqrt 2 half-widths. Miters are counted up to 1e6
    // half-widths, so that a limit of 1e308 cannot switch the culling off; a
    // longer spike from a join out of reach of the image is not drawn.
    const double reach = h * std::clamp(style.miter_limit, std::sqrt(2.0), 1e6) + tolerance;
    const Rect keep = visible.inflated(reach);
    const double size = std::max(
        {std::fabs(keep.x0), std::fabs(keep.x1), std::fabs(keep.y0), std::fabs(keep.y1), reach});
    if (size > kMaxMagnitude && std::isfinite(size))
        return outline_scaled(path, style, tolerance, visible, size);
    b.pieces.clear();
    if (style.dashes.empty())
        visible_part(path, keep, b.pieces, b.growth);
    else
        dashed(path, style, tolerance, keep, b.dash, b.pieces, b.growth);
    Outline outline(h, tolerance, style, b);
    std::size_t points = 0;
    for (const Pieces::Run& run : b.pieces.runs) {
        if (run.begin == run.end) continue; // a lone move_to draws nothing
        const std::size_t before = b.count;
        if (points >= kMaxOutlinePoints ||
            !outline.subpath(run.start, b.pieces.segments_of(run), run.closed, run.along,
                             kMaxOutlinePoints - points)) {
            // The hundreds of megabytes it took are not kept for the next
            // stroke (a batch's next files, a fuzzer's next inputs).
            b.release(b.count);
            break;
        }
        for (std::size_t i = before; i < b.count; ++i) points += b.polygons[i].size();
        b.growth.reached(points);
    }
    return {b.polygons.data(), b.count};
}

void Stroker::set_memory_budget(bool (*reserve)(std::size_t), void (*unreserve)(std::size_t)) {
    if (reserve == b_->growth.reserve && unreserve == b_->growth.unreserve) return;
    b_->growth.give_back();
    b_->growth.reserve = reserve;
    b_->growth.unreserve = unreserve;
}

void Stroker::release() { b_->release(0); }

std::size_t Stroker::reserved() const { return b_->growth.reserved; }

// outline() at 2^-k of the size, so that the largest magnitude is at most
// kMaxMagnitude, then scaled back: powers of two scale doubles exactly (the
// tolerance too stays far above the smallest normal double).
std::span<const Polygon> Stroker::outline_scaled(const Path& path, const StrokeGeometry& style,
                                                 double tolerance, const Rect& visible,
                                                 double size) {
    const double k = std::exp2(-std::ceil(std::log2(size / kMaxMagnitude)));
    Path scaled = path;
    scaled.transform(Affine::scale(k));
    StrokeGeometry st = style;
    st.width *= k;
    st.dash_offset *= k;
    for (double& d : st.dashes) d *= k;
    const Rect v{visible.x0 * k, visible.y0 * k, visible.x1 * k, visible.y1 * k};
    const std::span<const Polygon> out = outline(scaled, st, tolerance * k, v);
    for (std::size_t i = 0; i < b_->count; ++i)
        for (Point& p : b_->polygons[i]) p = Point{p.x / k, p.y / k};
    return out;
}

void stroke_outline(const Path& path, const StrokeGeometry& style, double tolerance,
                    std::vector<Polygon>& out, const Rect& visible) {
    Stroker stroker;
    for (const Polygon& poly : stroker.outline(path, style, tolerance, visible))
        out.push_back(poly);
}

} // namespace casteljau
