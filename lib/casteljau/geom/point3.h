// Point3 and Vec3: positions and displacements in space, kept distinct as in
// point.h (point - point = vector; no point + point, no scalar * point).
// `lerp` is written (1 - t) a + t b so that it is exact at t = 0 and t = 1:
// de Casteljau splits of surface patches keep their boundary rows bit for bit,
// which is what makes shared patch edges tessellate identically.
#pragma once

#include <cmath>

namespace casteljau {

/// A 3D displacement: the difference of two Point3.
struct Vec3 {
    double x = 0, y = 0, z = 0;

    /// Sum of vectors.
    constexpr Vec3 operator+(Vec3 v) const { return {x + v.x, y + v.y, z + v.z}; }
    /// Difference of vectors.
    constexpr Vec3 operator-(Vec3 v) const { return {x - v.x, y - v.y, z - v.z}; }
    /// The opposite vector.
    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    /// Scaled by s.
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    /// Divided by s.
    constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    /// Adds v.
    constexpr Vec3& operator+=(Vec3 v) { return *this = *this + v; }
    /// Subtracts v.
    constexpr Vec3& operator-=(Vec3 v) { return *this = *this - v; }
    /// Exact equality of every member.
    constexpr bool operator==(const Vec3&) const = default;

    /// Dot product.
    constexpr double dot(Vec3 v) const { return x * v.x + y * v.y + z * v.z; }
    /// Cross product (right-handed).
    constexpr Vec3 cross(Vec3 v) const {
        return {y * v.z - z * v.y, z * v.x - x * v.z, x * v.y - y * v.x};
    }
    /// Squared length.
    constexpr double length_sq() const { return dot(*this); }
    /// Length.
    double length() const { return std::sqrt(length_sq()); }
    /// The unit vector along *this; the zero vector stays zero.
    Vec3 normalized() const {
        const double l = length();
        return l > 0 ? *this / l : Vec3{};
    }
    /// Whether every component is finite.
    bool is_finite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }
};

constexpr Vec3 operator*(double s, Vec3 v) { return v * s; }

/// A 3D position (see Point for the algebra).
struct Point3 {
    double x = 0, y = 0, z = 0;

    /// The vector from p to this point.
    constexpr Vec3 operator-(Point3 p) const { return {x - p.x, y - p.y, z - p.z}; }
    /// This point moved by v.
    constexpr Point3 operator+(Vec3 v) const { return {x + v.x, y + v.y, z + v.z}; }
    /// This point moved by -v.
    constexpr Point3 operator-(Vec3 v) const { return {x - v.x, y - v.y, z - v.z}; }
    /// Exact equality of every member.
    constexpr bool operator==(const Point3&) const = default;

    /// The displacement from the origin, for affine combinations written as
    /// weighted sums (matrix forms, B-spline bases) whose weights sum to one.
    constexpr Vec3 to_vec() const { return {x, y, z}; }
    /// Whether every component is finite.
    bool is_finite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }
};

constexpr Point3 lerp(Point3 a, Point3 b, double t) {
    const double s = 1.0 - t;
    return {s * a.x + t * b.x, s * a.y + t * b.y, s * a.z + t * b.z};
}

constexpr Vec3 lerp(Vec3 a, Vec3 b, double t) {
    const double s = 1.0 - t;
    return {s * a.x + t * b.x, s * a.y + t * b.y, s * a.z + t * b.z};
}

inline double distance(Point3 a, Point3 b) { return (b - a).length(); }

/// An axis-aligned box; empty (lo > hi) until a point is added.
struct Box3 {
    Point3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};

    /// Grows the box to hold p.
    constexpr void add(Point3 p) {
        lo = {p.x < lo.x ? p.x : lo.x, p.y < lo.y ? p.y : lo.y, p.z < lo.z ? p.z : lo.z};
        hi = {p.x > hi.x ? p.x : hi.x, p.y > hi.y ? p.y : hi.y, p.z > hi.z ? p.z : hi.z};
    }
    /// Whether no point was added.
    constexpr bool empty() const { return lo.x > hi.x; }
    /// The centre of the box.
    constexpr Point3 center() const { return lerp(lo, hi, 0.5); }
    /// Length of the diagonal (0 when empty): the box's size.
    double diagonal() const { return empty() ? 0.0 : (hi - lo).length(); }
};

} // namespace casteljau
