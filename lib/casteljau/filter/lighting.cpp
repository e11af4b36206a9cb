// feDiffuseLighting and feSpecularLighting (Filter Effects 1, "Filter
// primitive feDiffuseLighting" #feDiffuseLightingElement, "Filter primitive
// feSpecularLighting" #feSpecularLightingElement, light sources
// #LightSourceDefinitions).
//
// The input's alpha is a height field Z(x, y) = surfaceScale * A(x, y). Its
// normal comes from the spec's Sobel kernels (dx = dy = 1 px):
//   N = (-surfaceScale * FACTOR_x * (K_x * A), -surfaceScale * FACTOR_y * (K_y * A), 1),
// normalized. The spec tabulates nine (K, FACTOR) pairs, for interior,
// edge and corner pixels of the window; they are all one rule, used here:
// for N_x, each row's difference A(x_r) - A(x_l) (x_l = x - 1 and x_r = x + 1,
// or x itself at an edge), weighted 1, 2, 1 for rows y - 1, y, y + 1 (a
// missing row weighs 0), times FACTOR_x = 2 / ((x_r - x_l) * (sum of the
// weights)); N_y likewise with rows and columns exchanged. (Interior:
// 2 / (2 * 4) = 1/4; left column: 2 / (1 * 4) = 1/2; top row: 2 / (2 * 3) =
// 1/3; corner: 2 / (1 * 3) = 2/3: the spec's factors.) A window one pixel
// wide has no x difference: N_x = 0 there (the spec's table has no case).
//
// L, the unit vector from the surface to the light, with each pixel at its
// device coordinates (x, y) (its top-left corner) and height Z(x, y):
//   distant: (cos az cos el, sin az cos el, sin el);
//   point, spot: normalize(light - (x, y, Z)).
// The light's color is lighting-color, times pow(-L.S, spotExponent) for a
// spot light (S the unit axis from the light to pointsAt), and 0 where
// -L.S <= 0 or, with a limiting cone, where -L.S < cos(cone angle): a hard
// cone edge (the spec's "should" smooth it; resvg does not either).
//
// diffuse:  RGB = kd * N.L * light color, A = 1;
// specular: RGB = ks * pow(N.H, specularExponent) * light color,
//           H = normalize(L + (0, 0, 1)), A = max(R, G, B);
// N.L and N.H below 0 light nothing. RGB are clamped to [0, 1] (so A is
// too). The diffuse result is opaque; the specular one is taken as already
// premultiplied (its colors are at most A by construction), as Chrome
// (Skia), Firefox, resvg and librsvg all take it: multiplying by A again
// would square every highlight, which a specular map added to a texture by
// the arithmetic feComposite (its intended use, 15.23) does not show.
//
// Invariants: alpha in [0, 1] and colors <= alpha by construction. Each
// pixel reads its 3 x 3 neighbourhood only, so a window cut elsewhere gives
// the same bits one pixel away from the cut.
#include "casteljau/filter/lighting.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace casteljau {

namespace {

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 scaled(const Vec3& v, double k) { return {v.x * k, v.y * k, v.z * k}; }
Vec3 normalized(const Vec3& v) {
    const double n = std::sqrt(dot(v, v));
    return n > 0 ? scaled(v, 1 / n) : Vec3{};
}

double radians(double degrees) { return degrees * (std::numbers::pi / 180); }

// The surface normal at window (x, y): the spec's kernels, as one rule.
Vec3 normal(const FilterImage& in, int x, int y, double surface_scale) {
    const int w = in.width(), h = in.height();
    const int xl = x > 0 ? x - 1 : x, xr = x < w - 1 ? x + 1 : x;
    const int yt = y > 0 ? y - 1 : y, yb = y < h - 1 ? y + 1 : y;
    // Weights of the neighbouring rows (columns): 1 when present, else 0.
    const double wl = xl < x ? 1 : 0, wr = x < xr ? 1 : 0;
    const double wt = yt < y ? 1 : 0, wb = y < yb ? 1 : 0;
    auto a = [&](int i, int j) { return double(in.at(i, j).a); };
    const double gx =
        wt * (a(xr, yt) - a(xl, yt)) + 2 * (a(xr, y) - a(xl, y)) + wb * (a(xr, yb) - a(xl, yb));
    const double gy =
        wl * (a(xl, yb) - a(xl, yt)) + 2 * (a(x, yb) - a(x, yt)) + wr * (a(xr, yb) - a(xr, yt));
    const double nx = xr > xl ? -surface_scale * 2 / ((xr - xl) * (wt + 2 + wb)) * gx : 0;
    const double ny = yb > yt ? -surface_scale * 2 / ((yb - yt) * (wl + 2 + wr)) * gy : 0;
    return normalized({nx, ny, 1});
}

// What a light gives a surface point: the unit vector towards the light and
// the light's color there.
struct Sample {
    Vec3 l, color;
};

struct Distant {
    Vec3 l, color;
    Sample at(const Vec3&) const { return {l, color}; }
};

struct Positional {
    Vec3 pos, color;
    Sample at(const Vec3& p) const { return {normalized(pos - p), color}; }
};

struct Spot {
    Vec3 pos, axis, color;
    double exponent = 1, cos_cone = -1; // cos_cone -1: no cone
    Sample at(const Vec3& p) const {
        const Vec3 l = normalized(pos - p);
        const double minus_ls = -dot(l, axis);
        if (!(minus_ls > 0) || minus_ls < cos_cone) return {l, {}};
        return {l, scaled(color, std::pow(minus_ls, exponent))};
    }
};

float unit(double v) { return float(v > 0 ? (v < 1 ? v : 1) : 0); }

template <class Light>
void shade(const FilterImage& in, FilterImage& out, const Subregion& sub, const Lighting& lt,
           const Light& light) {
    for (int y = sub.y0; y < sub.y1; ++y)
        for (int x = sub.x0; x < sub.x1; ++x) {
            const Vec3 n = normal(in, x, y, lt.surface_scale);
            const Vec3 p{double(in.box.x0 + x), double(in.box.y0 + y),
                         lt.surface_scale * in.at(x, y).a};
            const Sample s = light.at(p);
            if (!lt.specular) {
                const double k = lt.constant * std::max(dot(n, s.l), 0.0);
                out.at(x, y) = {unit(k * s.color.x), unit(k * s.color.y), unit(k * s.color.z), 1};
                continue;
            }
            const double nh = dot(n, normalized({s.l.x, s.l.y, s.l.z + 1}));
            const double k = lt.constant * (nh > 0 ? std::pow(nh, lt.specular_exponent) : 0);
            const float r = unit(k * s.color.x), g = unit(k * s.color.y), b = unit(k * s.color.z);
            const float a = std::max({r, g, b});
            out.at(x, y) = {r, g, b, a};
        }
}

} // namespace

void lighting(const FilterImage& in, FilterImage& out, const Subregion& sub,
              const Lighting& l) noexcept {
    if (sub.empty()) return;
    const Vec3 color{l.color.r, l.color.g, l.color.b};
    if (const auto* d = std::get_if<DistantLight>(&l.light)) {
        const double az = radians(d->azimuth), el = radians(d->elevation);
        const Vec3 dir{std::cos(az) * std::cos(el), std::sin(az) * std::cos(el), std::sin(el)};
        shade(in, out, sub, l, Distant{dir, color});
    } else if (const auto* p = std::get_if<PointLight>(&l.light)) {
        shade(in, out, sub, l, Positional{{p->x, p->y, p->z}, color});
    } else if (const auto* s = std::get_if<SpotLight>(&l.light)) {
        const Vec3 pos{s->x, s->y, s->z};
        Spot spot{pos, normalized(Vec3{s->at_x, s->at_y, s->at_z} - pos), color,
                  s->specular_exponent, -1};
        if (s->cone_angle) spot.cos_cone = std::cos(radians(std::abs(*s->cone_angle)));
        shade(in, out, sub, l, spot);
    }
}

} // namespace casteljau
