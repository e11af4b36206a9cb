// Point and Vec2: positions and displacements in the plane, kept distinct.
//
// The algebra is the affine one: point - point = vector, point + vector = point,
// vector arithmetic is a vector space; there is no point + point and no
// scalar * point. Interpolation between points is `lerp`, which is exact at
// t = 0 and t = 1 (it is written (1 - t) a + t b, not a + t (b - a)), so de
// Casteljau constructions reproduce their end points bit for bit.
#pragma once

#include <cmath>

namespace casteljau {

/// A 2D displacement: the difference of two points.
struct Vec2 {
    double x = 0, y = 0;

    /// Sum of vectors.
    constexpr Vec2 operator+(Vec2 v) const { return {x + v.x, y + v.y}; }
    /// Difference of vectors.
    constexpr Vec2 operator-(Vec2 v) const { return {x - v.x, y - v.y}; }
    /// The opposite vector.
    constexpr Vec2 operator-() const { return {-x, -y}; }
    /// Scaled by s.
    constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
    /// Divided by s.
    constexpr Vec2 operator/(double s) const { return {x / s, y / s}; }
    /// Adds v.
    constexpr Vec2& operator+=(Vec2 v) { return *this = *this + v; }
    /// Subtracts v.
    constexpr Vec2& operator-=(Vec2 v) { return *this = *this - v; }
    /// Scales by s.
    constexpr Vec2& operator*=(double s) { return *this = *this * s; }
    /// Exact equality of every member.
    constexpr bool operator==(const Vec2&) const = default;

    /// Dot product.
    constexpr double dot(Vec2 v) const { return x * v.x + y * v.y; }
    /// z component of the 3D cross product: positive when v turns left of *this.
    constexpr double cross(Vec2 v) const { return x * v.y - y * v.x; }
    /// Squared length.
    constexpr double length_sq() const { return dot(*this); }
    /// sqrt of the sum of squares, not std::hypot: hypot guards against overflow
    /// beyond 1e154, which finite geometry here never reaches, at ~10x the cost.
    double length() const { return std::sqrt(x * x + y * y); }
    /// The unit vector along *this; the zero vector stays zero.
    Vec2 normalized() const {
        const double l = length();
        return l > 0 ? *this / l : Vec2{};
    }
    /// Left-hand perpendicular (rotated +90 degrees in a y-up frame).
    constexpr Vec2 perp() const { return {-y, x}; }
    /// Whether every component is finite.
    bool is_finite() const { return std::isfinite(x) && std::isfinite(y); }
};

constexpr Vec2 operator*(double s, Vec2 v) { return v * s; }

/// A 2D position: point - point is a Vec2, point + vector a Point, point + point nothing.
struct Point {
    double x = 0, y = 0;

    /// The vector from p to this point.
    constexpr Vec2 operator-(Point p) const { return {x - p.x, y - p.y}; }
    /// This point moved by v.
    constexpr Point operator+(Vec2 v) const { return {x + v.x, y + v.y}; }
    /// This point moved by -v.
    constexpr Point operator-(Vec2 v) const { return {x - v.x, y - v.y}; }
    /// Moves this point by v.
    constexpr Point& operator+=(Vec2 v) { return *this = *this + v; }
    /// Exact equality of every member.
    constexpr bool operator==(const Point&) const = default;

    /// The displacement from the origin: for the rare place where a point's
    /// coordinates are used as a vector (power-basis coefficients, centroids).
    constexpr Vec2 to_vec() const { return {x, y}; }
    /// Whether every component is finite.
    bool is_finite() const { return std::isfinite(x) && std::isfinite(y); }
};

constexpr Point lerp(Point a, Point b, double t) {
    const double s = 1.0 - t;
    return {s * a.x + t * b.x, s * a.y + t * b.y};
}

constexpr Vec2 lerp(Vec2 a, Vec2 b, double t) {
    const double s = 1.0 - t;
    return {s * a.x + t * b.x, s * a.y + t * b.y};
}

constexpr Point midpoint(Point a, Point b) { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; }

inline double distance(Point a, Point b) { return (b - a).length(); }

/// Distance from p to the closed segment [a, b]; a degenerate segment is a point.
inline double distance_to_segment(Point p, Point a, Point b) {
    const Vec2 ab = b - a, ap = p - a;
    const double len_sq = ab.length_sq();
    if (len_sq == 0.0) return ap.length();
    double t = ap.dot(ab) / len_sq;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return (p - lerp(a, b, t)).length();
}

/// A squared distance as the fraction num / den (den > 0), for callers that
/// compare it and need no division.
struct SquaredDistance {
    double num, den;
};

/// The squared distance from a + u to the closed segment from a to a + v:
/// to the nearer end where the point projects outside the segment (or the
/// segment is a point), else to its line, cross(u, v)^2 / |v|^2.
inline SquaredDistance segment_distance_sq(Vec2 u, Vec2 v) {
    const double along = u.dot(v), len_sq = v.length_sq();
    if (along <= 0 || len_sq == 0) return {u.length_sq(), 1};
    if (along >= len_sq) return {(u - v).length_sq(), 1};
    const double across = u.cross(v);
    return {across * across, len_sq};
}

} // namespace casteljau
