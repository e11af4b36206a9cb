// Affine: a 2D affine map in the SVG `matrix(a b c d e f)` convention,
//   x' = a x + c y + e,   y' = b x + d y + f.
// Applied to a Point it translates; applied to a Vec2 it does not. Composition
// reads right to left like the maths: (A * B) * p == A * (B * p).
#pragma once

#include "casteljau/geom/point.h"
#include "casteljau/geom/rect.h"

#include <cmath>
#include <numbers>

namespace casteljau {

/// A 2D affine map x' = a x + c y + e, y' = b x + d y + f (SVG matrix order).
struct Affine {
    double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

    /// The identity map.
    static constexpr Affine identity() { return {}; }
    /// Translation by v.
    static constexpr Affine translate(Vec2 v) { return {1, 0, 0, 1, v.x, v.y}; }
    /// Scaling by sx along x and sy along y.
    static constexpr Affine scale(double sx, double sy) { return {sx, 0, 0, sy, 0, 0}; }
    /// Uniform scaling by s.
    static constexpr Affine scale(double s) { return scale(s, s); }
    /// Rotation by `radians` (towards +y from +x).
    static Affine rotate(double radians) {
        const double cs = std::cos(radians), sn = std::sin(radians);
        return {cs, sn, -sn, cs, 0, 0};
    }
    /// Skew along x by `radians` (SVG skewX).
    static Affine skew_x(double radians) { return {1, 0, std::tan(radians), 1, 0, 0}; }
    /// Skew along y by `radians` (SVG skewY).
    static Affine skew_y(double radians) { return {1, std::tan(radians), 0, 1, 0, 0}; }

    /// Maps a point (with the translation).
    constexpr Point operator*(Point p) const {
        return {a * p.x + c * p.y + e, b * p.x + d * p.y + f};
    }
    /// Maps a vector (without the translation).
    constexpr Vec2 operator*(Vec2 v) const { return {a * v.x + c * v.y, b * v.x + d * v.y}; }
    /// Composition: (this * m) applies m first, then this.
    constexpr Affine operator*(const Affine& m) const {
        return {a * m.a + c * m.b, b * m.a + d * m.b,     a * m.c + c * m.d,
                b * m.c + d * m.d, a * m.e + c * m.f + e, b * m.e + d * m.f + f};
    }
    /// Exact equality of every member.
    constexpr bool operator==(const Affine&) const = default;

    /// Determinant of the linear part (area scale; negative when mirroring).
    constexpr double determinant() const { return a * d - b * c; }
    /// Precondition: determinant() != 0.
    constexpr Affine inverse() const {
        const double inv = 1.0 / determinant();
        return {d * inv, -b * inv, -c * inv, a * inv, (c * f - d * e) * inv, (b * e - a * f) * inv};
    }
    /// Largest factor by which the map stretches any vector: the larger singular value.
    /// Used to turn a device-pixel tolerance into a user-space one.
    double max_scale() const {
        const double p = a * a + b * b, q = c * c + d * d, r = a * c + b * d;
        const double mean = 0.5 * (p + q), dev = std::hypot(0.5 * (p - q), r);
        return std::sqrt(mean + dev);
    }
    /// Whether every component is finite.
    bool is_finite() const {
        return std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d) &&
               std::isfinite(e) && std::isfinite(f);
    }
};

constexpr double degrees_to_radians(double deg) { return deg * (std::numbers::pi / 180.0); }

/// The box of `b` mapped by `m`: its four corners mapped (conservative
/// under rotation, exact otherwise); empty when `b` is.
inline Rect mapped_box(const Rect& b, const Affine& m) {
    if (b.is_empty()) return b;
    return Rect::from_points(m * b.min(), m * b.max())
        .united(m * Point{b.x0, b.y1})
        .united(m * Point{b.x1, b.y0});
}

} // namespace casteljau
