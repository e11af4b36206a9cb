// Bezier: a Bezier curve of any degree 1..kMaxDegree chosen at run time,
// stored inline (no allocation), with the same operations as Bez<N>.
// It is what B-splines convert to and what a user of higher degrees builds.
#pragma once

#include "casteljau/curve/decasteljau.h"
#include "casteljau/geom/affine.h"
#include "casteljau/geom/rect.h"

#include <array>
#include <span>

namespace casteljau {

// Power-basis form of a runtime-degree curve: c0 + sum_j c[j-1] t^j.
struct PowerForm {
    Point c0;
    std::array<Vec2, kMaxDegree> c{};
    int degree = 0;
    constexpr Point eval(double t) const {
        return horner_eval(c0, std::span<const Vec2>(c.data(), std::size_t(degree)), t);
    }
};

struct Bezier {
    int degree = 1;
    std::array<Point, kMaxPoints> p{};

    // Precondition: 2 <= pts.size() <= kMaxPoints.
    static Bezier from(std::span<const Point> pts);

    Point start() const { return p[0]; }
    Point end() const { return p[std::size_t(degree)]; }
    std::span<const Point> points() const { return {p.data(), std::size_t(degree) + 1}; }

    Point eval(double t) const { return decasteljau_eval(points(), t); }
    Point eval_bernstein(double t) const { return bernstein_eval(points(), t); }
    PowerForm power() const;
    Vec2 deriv(double t) const;
    Vec2 deriv2(double t) const;

    std::array<Bezier, 2> split(double t) const;
    Bezier subsegment(double t0, double t1) const;
    // Precondition: degree < kMaxDegree.
    Bezier elevate() const;
    Bezier transformed(const Affine& m) const;
    Rect control_bounds() const;
    Rect bounds() const;

    bool operator==(const Bezier& o) const;
};

} // namespace casteljau
