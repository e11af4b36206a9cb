#include "casteljau/render3d/mesh_raster.h"

#include "casteljau/geom/pixel_index.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

namespace {

constexpr int kGrid = 4;                // samples a pixel side
constexpr int kSamples = kGrid * kGrid; // 16: one 8-bit step is 1/255, 16 levels is plenty
constexpr int kBand = 16;               // rows a band: 16 x 16 samples x 20 B x width
constexpr float kAmbient = 0.18f, kDiffuse = 0.82f, kSpecular = 0.3f;
constexpr double kShininess = 48;
const Rgb kWire{0.05f, 0.05f, 0.08f};

using Vertex = MeshRenderer::ScreenVertex;

Vertex lerp_vertex(const Vertex& a, const Vertex& b, double t) {
    return {lerp(a.c, b.c, t), lerp(a.n, b.n, t), lerp(a.st, b.st, t), {}, 0};
}

float linear_to_srgb(float c) {
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1 / 2.4f) - 0.055f;
}

double edge(Point a, Point b, Point p) { return (b - a).cross(p - a); }

} // namespace

void MeshRenderer::setup(const Mesh& mesh, const ScreenProjection& view) {
    verts_.resize(mesh.positions.size());
    for (std::size_t i = 0; i < verts_.size(); ++i) {
        const Vec3 n = mesh.normals[i];
        verts_[i] = {view.to_camera(mesh.positions[i]),
                     {n.dot(view.right), n.dot(view.down), n.dot(view.forward)},
                     mesh.st[i],
                     {},
                     0};
    }
    tris_.clear();
    for (const auto& t : mesh.triangles) {
        const Vertex* v[3] = {&verts_[t[0]], &verts_[t[1]], &verts_[t[2]]};
        // Clip against z = near (Sutherland-Hodgman, one plane): 0, 3 or 4 corners.
        Vertex poly[4];
        int n = 0;
        for (int k = 0; k < 3; ++k) {
            const Vertex& a = *v[k];
            const Vertex& b = *v[(k + 1) % 3];
            const bool ina = a.c.z >= view.near, inb = b.c.z >= view.near;
            if (ina) poly[n++] = a;
            if (ina != inb) poly[n++] = lerp_vertex(a, b, (view.near - a.c.z) / (b.c.z - a.c.z));
        }
        for (int k = 1; k + 1 < n; ++k) add_triangle({poly[0], poly[k], poly[k + 1]}, view);
    }
    std::sort(tris_.begin(), tris_.end(),
              [](const ScreenTriangle& a, const ScreenTriangle& b) { return a.y0 < b.y0; });
}

void MeshRenderer::add_triangle(const Vertex (&v)[3], const ScreenProjection& view) {
    ScreenTriangle t;
    for (int k = 0; k < 3; ++k) {
        t.v[k] = v[k];
        t.v[k].w = 1 / std::max(v[k].c.z, view.near);
        t.v[k].px = view.to_pixels({v[k].c.x, v[k].c.y, std::max(v[k].c.z, view.near)});
    }
    const double area = edge(t.v[0].px, t.v[1].px, t.v[2].px);
    if (!(std::abs(area) > 1e-12)) return; // edge-on or degenerate: covers no sample
    t.y0 = std::min({t.v[0].px.y, t.v[1].px.y, t.v[2].px.y});
    t.y1 = std::max({t.v[0].px.y, t.v[1].px.y, t.v[2].px.y});
    if (t.y1 < 0 || t.y0 > view.height) return;
    // d(s, t)/d(pixel) of the affine screen-space map: the filter footprint.
    const Vec2 e1 = t.v[1].px - t.v[0].px, e2 = t.v[2].px - t.v[0].px;
    const Vec2 s1 = t.v[1].st - t.v[0].st, s2 = t.v[2].st - t.v[0].st;
    const double dsdx = (s1.x * e2.y - s2.x * e1.y) / area,
                 dsdy = (s2.x * e1.x - s1.x * e2.x) / area;
    const double dtdx = (s1.y * e2.y - s2.y * e1.y) / area,
                 dtdy = (s2.y * e1.x - s1.y * e2.x) / area;
    t.footprint = {std::abs(dsdx) + std::abs(dsdy), std::abs(dtdx) + std::abs(dtdy)};
    tris_.push_back(t);
}

void MeshRenderer::render(const Mesh& mesh, const ScreenProjection& view, const MeshStyle& style,
                          Canvas& canvas) {
    setup(mesh, view);
    const int width = canvas.width();
    depth_.resize(std::size_t(width) * kBand * kSamples);
    color_.resize(depth_.size());
    for (int y0 = 0; y0 < canvas.height(); y0 += kBand)
        draw_band(y0, std::min(y0 + kBand, canvas.height()), width, style, canvas);
}

void MeshRenderer::draw_band(int y0, int y1, int width, const MeshStyle& style, Canvas& canvas) {
    std::fill(depth_.begin(), depth_.end(), 0.0f);
    for (const ScreenTriangle& t : tris_) {
        if (t.y0 >= y1) break; // sorted by top row
        if (t.y1 >= y0) draw_triangle(t, y0, y1, width, style);
    }
    for (int y = y0; y < y1; ++y) {
        Premul* row = canvas.row(y);
        for (int x = 0; x < width; ++x) {
            const std::size_t base = (std::size_t(y - y0) * width + x) * kSamples;
            Rgb sum;
            int covered = 0;
            for (int s = 0; s < kSamples; ++s) {
                if (depth_[base + s] == 0) continue;
                ++covered;
                sum.r += color_[base + s].r, sum.g += color_[base + s].g,
                    sum.b += color_[base + s].b;
            }
            if (covered == 0) continue;
            const float a = float(covered) / kSamples, inv = 1.0f / covered;
            const Premul c{a * linear_to_srgb(sum.r * inv), a * linear_to_srgb(sum.g * inv),
                           a * linear_to_srgb(sum.b * inv), a};
            blend_over(row[x], c, 1.0f);
        }
    }
}

Rgb MeshRenderer::shade(const ScreenTriangle& t, const double (&lambda)[3], double edge_px,
                        const MeshStyle& style) const {
    // Perspective-correct weights: screen barycentrics scaled by 1/z, renormalised.
    double b[3], sum = 0;
    for (int k = 0; k < 3; ++k) sum += (b[k] = std::max(0.0, lambda[k]) * t.v[k].w);
    Vec3 n{}, pos{};
    Vec2 st{};
    for (int k = 0; k < 3; ++k) {
        n += (b[k] / sum) * t.v[k].n;
        pos += (b[k] / sum) * t.v[k].c;
        st += (b[k] / sum) * t.v[k].st.to_vec();
    }
    const Vec3 view = (-pos).normalized();
    if (n.length_sq() == 0) n = (t.v[1].c - t.v[0].c).cross(t.v[2].c - t.v[0].c);
    n = n.normalized();
    if (n.dot(view) < 0) n = -n;
    const Vec3 light = Vec3{-0.5, -0.7, -1.0}.normalized(); // toward the light, camera space
    const Rgb albedo = style.texture ? style.texture->at(Point{} + st, t.footprint) : style.albedo;
    const float diffuse = kAmbient + kDiffuse * float(std::max(0.0, n.dot(light)));
    const float spec =
        kSpecular * float(std::pow(std::max(0.0, n.dot((light + view).normalized())), kShininess));
    Rgb color{albedo.r * diffuse + spec, albedo.g * diffuse + spec, albedo.b * diffuse + spec};
    if (style.wireframe) {
        const float k = float(std::clamp(1.0 - edge_px, 0.0, 1.0));
        color = {color.r + k * (kWire.r - color.r), color.g + k * (kWire.g - color.g),
                 color.b + k * (kWire.b - color.b)};
    }
    return color;
}

void MeshRenderer::draw_triangle(const ScreenTriangle& t, int y0, int y1, int width,
                                 const MeshStyle& style) {
    // Barycentrics are affine in the pixel position: lambda_k(p) = l0[k] + g[k] . p,
    // so each sample is one multiply-add away from its pixel's corner value.
    const Point a = t.v[0].px, b = t.v[1].px, c = t.v[2].px;
    const double area = edge(a, b, c), inv_area = 1 / area;
    const Point from[3] = {b, c, a}, to[3] = {c, a, b};
    double l0[3], gx[3], gy[3], px_per_unit[3], offset[3][kSamples];
    for (int k = 0; k < 3; ++k) {
        const Vec2 e = to[k] - from[k];
        gx[k] = -e.y * inv_area, gy[k] = e.x * inv_area;
        l0[k] = edge(from[k], to[k], {}) * inv_area;
        px_per_unit[k] = std::abs(area) / e.length(); // lambda 1 is this many px from the edge
        for (int s = 0; s < kSamples; ++s)
            offset[k][s] = gx[k] * (s % kGrid + 0.5) / kGrid + gy[k] * (s / kGrid + 0.5) / kGrid;
    }
    const int xa = floor_in(std::min({a.x, b.x, c.x}), 0, width);
    const int xb = floor_in(std::max({a.x, b.x, c.x}), -1, width - 1);
    const int ya = floor_in(t.y0, y0, y1);
    const int yb = floor_in(t.y1, y0 - 1, y1 - 1);
    for (int y = ya; y <= yb; ++y)
        for (int x = xa; x <= xb; ++x) {
            double corner[3];
            for (int k = 0; k < 3; ++k) corner[k] = l0[k] + gx[k] * x + gy[k] * y;
            const std::size_t base = (std::size_t(y - y0) * width + x) * kSamples;
            unsigned mask = 0;
            for (int s = 0; s < kSamples; ++s) {
                const double s0 = corner[0] + offset[0][s], s1 = corner[1] + offset[1][s],
                             s2 = corner[2] + offset[2][s];
                if (s0 < 0 || s1 < 0 || s2 < 0) continue;
                const float w = float(s0 * t.v[0].w + s1 * t.v[1].w + s2 * t.v[2].w);
                if (w <= depth_[base + s]) continue;
                depth_[base + s] = w;
                mask |= 1u << s;
            }
            if (!mask) continue;
            // Shade once, at the pixel centre (clamped into the triangle by shade()).
            double centre[3], edge_px = INFINITY;
            for (int k = 0; k < 3; ++k) {
                centre[k] = corner[k] + 0.5 * (gx[k] + gy[k]);
                edge_px = std::min(edge_px, std::abs(centre[k]) * px_per_unit[k]);
            }
            const Rgb color = shade(t, centre, edge_px, style);
            for (int s = 0; s < kSamples; ++s)
                if (mask & (1u << s)) color_[base + s] = color;
        }
}

} // namespace casteljau
