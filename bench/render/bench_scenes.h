// Seeded benchmark scenes at 1024 x 1024, built as Scenes so that every
// renderer under comparison draws exactly the same geometry.
#pragma once

#include "casteljau/scene/scene.h"

#include <string>
#include <vector>

namespace casteljau::bench {

inline constexpr double kSceneSize = 1024;

/// A named scene.
struct NamedScene {
    std::string name; ///< benchmark label
    Scene scene;      ///< 1024 x 1024 device pixels
};

/// `n` filled closed blobs of four cubics each, 10 to 60 px across, translucent.
Scene random_blobs(unsigned seed, int n);
/// One ellipse filling most of the canvas (SVG arcs: conics).
Scene large_ellipse();
/// `n` hairline strokes (1 px wide lines and cubics, up to 120 px long).
Scene hairlines(unsigned seed, int n);
/// `n` glyph-sized shapes (8 to 16 px): rings with holes and curved strokes of letters.
Scene glyph_shapes(unsigned seed, int n);
/// One opaque rectangle covering the canvas.
Scene full_canvas_rect();

/// The scene list: 2k and 20k blobs, the ellipse, 10k hairlines,
/// 5k glyph shapes and the full-canvas rectangle.
std::vector<NamedScene> standard_scenes();

/// A seeded side x side image stretched over the canvas, level or turned by
/// 10 degrees about its centre (and grown to cover the canvas): 512 px
/// drawn at 2x, or 2900 px drawn at 1/2.83 (sampled from its level 1).
Scene stretched_image(unsigned seed, int side, bool turned);
/// The canvas filled with a gradient of three opaque stops: linear along the
/// diagonal, or radial with its focal point off the centre.
Scene gradient_fill(Gradient::Kind kind);
/// `n` rectangles 10 to 64 px across, filled with one 16 px pattern tile (a
/// square, a disc and a stroked cross), in user space.
Scene pattern_rects(unsigned seed, int n);

/// Shaded paints, by rows (paint/image_shader.h, paint/gradient.h): the
/// stretched images, the two gradients and 2k pattern-filled rectangles.
std::vector<NamedScene> paint_scenes();

} // namespace casteljau::bench
