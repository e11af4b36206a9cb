// Triangle meshes to pixels: z-buffer, 16 samples a pixel, Blinn-Phong.
//
// Visibility is resolved per sample (a 4 x 4 grid in each pixel) against a
// z-buffer of 1/z, which is affine in screen space and so exact to
// interpolate; colour is computed once per pixel and triangle (at the pixel
// centre, clamped into the triangle), as multisampling does, and written to
// the samples that triangle wins. A pixel's colour is the mean of its samples
// in linear light, its alpha the fraction covered: edges and silhouettes are
// antialiased with 16 levels.
//
// Shading, in camera space: albedo (texture or plain) times (ambient +
// diffuse max(0, n.l)) (Lambert), plus a white Blinn-Phong highlight
// max(0, n.h)^48 with h = (l + v) / |l + v| (Blinn 1977). Normals are
// interpolated perspective-correctly, renormalised and flipped toward the
// viewer (two-sided). The key light comes from above-left of the camera.
// Wireframe draws each triangle's edges about 1 px wide on top, hidden
// edges hidden (it is part of the triangle's own shading).
//
// Triangles crossing the near plane are clipped to it in camera space.
// Frames are drawn in bands of rows so that the sample buffers (20 bytes a
// sample) stay small; all buffers are kept across frames.
#pragma once

#include "casteljau/paint/canvas.h"
#include "casteljau/render3d/texture.h"
#include "casteljau/tessellate/mesh.h"
#include "casteljau/tessellate/projection.h"

#include <vector>

namespace casteljau {

/// How a mesh is shaded: texture or albedo, lights, wireframe.
struct MeshStyle {
    const Texture* texture = nullptr; ///< nullptr: the plain albedo below
    Rgb albedo{0.75f, 0.75f, 0.75f};
    bool wireframe = false;
};

/// The 3D rasterizer: meshes to pixels with a multisampled z-buffer.
class MeshRenderer {
  public:
    /// Composites the mesh (source-over) onto `canvas`, which must be the
    /// projection's width x height.
    void render(const Mesh& mesh, const ScreenProjection& view, const MeshStyle& style,
                Canvas& canvas);

    /// A vertex after projection.
    struct ScreenVertex {
        Vec3 c; ///< camera space
        Vec3 n; ///< camera-space normal
        Point st;
        Point px; ///< pixel position
        double w; ///< 1 / depth
    };
    /// A projected triangle ready to scan.
    struct ScreenTriangle {
        ScreenVertex v[3];
        double y0, y1;  ///< rows covered
        Vec2 footprint; ///< (s, t) extent of one pixel
    };

  private:
    void setup(const Mesh& mesh, const ScreenProjection& view);
    void add_triangle(const ScreenVertex (&v)[3], const ScreenProjection& view);
    void draw_band(int y0, int y1, int width, const MeshStyle& style, Canvas& canvas);
    void draw_triangle(const ScreenTriangle& t, int y0, int y1, int width, const MeshStyle& style);
    /// The colour at screen barycentrics `lambda`, `edge_px` from the nearest edge.
    Rgb shade(const ScreenTriangle& t, const double (&lambda)[3], double edge_px,
              const MeshStyle& style) const;

    std::vector<ScreenVertex> verts_;
    std::vector<ScreenTriangle> tris_;
    std::vector<float> depth_; ///< per sample: 1/z, 0 where empty
    std::vector<Rgb> color_;   ///< per sample, linear
};

} // namespace casteljau
