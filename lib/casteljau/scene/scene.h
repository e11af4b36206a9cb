// Scene: what gets drawn, independent of where it came from (the SVG reader
// builds one; an application can build one directly).
//
// A scene is a tree of groups and shapes, resolved: nothing in it refers to
// anything by name, and nothing inherits. Each shape carries its path in user
// space, the full transform from user space to the scene's device space (the
// product of its ancestors' transforms, its own and the viewBox mapping), and
// its paint. A group carries what needs its children drawn together into an
// offscreen layer first: opacity, a clip, a mask, a blend mode, isolation.
// A group without any of these is the same as its children drawn in its
// place, and builders flatten it away.
//
// Clips and masks are drawn content too (`Mask`): a clip path is a mask of
// its shapes' alpha, drawn as opaque fills; the transforms of a mask's
// content are, like every shape's, to the scene's device space. A clip or
// mask on a clip path or a mask is the content group's own clip or mask.
// A pattern's content has its transforms to the pattern's tile space
// instead: it is drawn once per paint into a tile at device resolution.
// Filters are graphs of pixel operations on a group's layer (filter/graph.h),
// run before its clip, mask and opacity (Filter Effects 1, 3, and CSS
// Masking 1, 1).
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/filter/graph.h"
#include "casteljau/paint/blend.h"
#include "casteljau/paint/color.h"
#include "casteljau/paint/gradient.h"
#include "casteljau/paint/mask.h"
#include "casteljau/paint/raster_image.h"
#include "casteljau/raster/sweep.h"

#include <memory>
#include <optional>
#include <variant>
#include <vector>

namespace casteljau {

struct Pattern;

/// How a shape is filled: paint, opacity and fill rule.
struct Fill {
    Rgba color;                               ///< used when there is no gradient nor pattern
    std::shared_ptr<const Gradient> gradient; ///< shared by every shape that uses it
    float opacity = 1;                        ///< fill-opacity
    FillRule rule = FillRule::NonZero;
    std::shared_ptr<const Pattern> pattern = nullptr; ///< paints instead of color and gradient
};

enum class LineJoin { Miter, Round, Bevel };
enum class LineCap { Butt, Round, Square };

/// The shape of a stroke, its paint apart: all that the stroker needs, and
/// what the SVG style cascade computes (initial values of SVG 1.1, 11.4).
struct StrokeGeometry {
    double width = 1;
    LineJoin join = LineJoin::Miter;
    LineCap cap = LineCap::Butt;
    double miter_limit = 4;
    std::vector<double> dashes;
    double dash_offset = 0;
};

/// How a shape is stroked: paint, opacity and geometry.
struct Stroke {
    Rgba color;                               ///< used when there is no gradient nor pattern
    std::shared_ptr<const Gradient> gradient; ///< shared by every shape that uses it
    float opacity = 1;
    StrokeGeometry geometry;
    std::shared_ptr<const Pattern> pattern = nullptr; ///< paints instead of color and gradient
};

/// A path with its transform, fill, stroke and opacity.
struct Shape {
    Path path;
    Affine transform; ///< user space -> scene device space
    std::optional<Fill> fill;
    std::optional<Stroke> stroke;
    float opacity = 1; ///< the element's own opacity
    /// Stroke drawn before the fill (SVG 2 paint-order: stroke fill), not after.
    bool stroke_first = false;
    /// Antialiased edges; false samples pixel centres, for this shape only
    /// (SVG shape-rendering: crispEdges and optimizeSpeed).
    bool antialias = true;
    int source_line = 0;
};

struct Node;
struct Mask;
struct Filter;

/// Children drawn together into a layer when any of opacity, clip, mask,
/// blend mode or isolation asks for one; then clipped, masked, and
/// composited onto what is under it with the opacity and blend mode.
struct Group {
    float opacity = 1;
    std::vector<Node> children;
    /// mix-blend-mode: how the layer combines with its backdrop (Compositing 1, 5).
    BlendMode blend = BlendMode::Normal;
    /// isolation: isolate. Blend modes inside blend with this group's layer
    /// only, not with what is under the group (Compositing 1, 3.2). Opacity,
    /// a clip, a mask or a blend mode isolate a group too.
    bool isolate = false;
    std::shared_ptr<const Mask> clip = nullptr; ///< a clip path (an alpha mask); none when null
    std::shared_ptr<const Mask> mask = nullptr; ///< a mask; none when null
    /// filter: applied in order, each to the result of the one before.
    std::vector<std::shared_ptr<const Filter>> filters = {};

    /// Whether the children must be drawn into a layer first.
    bool needs_layer() const {
        return opacity < 1 || blend != BlendMode::Normal || isolate || clip || mask ||
               !filters.empty();
    }
};

/// A shape or a group.
struct Node {
    std::variant<Shape, Group> item;
};

/// A coverage mask from drawn content: each pixel of a masked layer is
/// scaled by the value `kind` takes from `content` drawn at that pixel.
struct Mask {
    MaskKind kind = MaskKind::Alpha;
    Group content; ///< transforms to scene device space, as every shape's
};

/// A filter on a group: its graph in the filtered element's user space, and
/// the drawings that its feImage, FillPaint and StrokePaint inputs read.
struct Filter {
    FilterGraph graph;
    Affine transform;          ///< the graph's user space -> scene device space
    std::vector<Group> images; ///< feImage content (ImageInput::index), to scene device space
    Group fill_paint;          ///< FillPaint: the filter region painted with the element's fill
    Group stroke_paint;        ///< StrokePaint: the same with its stroke's paint
};

/// A paint that repeats a tile over the plane: a pattern's drawn content, or
/// an image's pixels (once, for `<image>`, or repeated).
struct Pattern {
    double width = 0, height = 0; ///< the tile is [0, width] x [0, height] in tile space
    Affine transform;             ///< tile space -> the painted shape's user space
    /// The tile's content, transforms to tile space; drawn at the device
    /// resolution of each shape it paints, clipped to the tile.
    Group content;
    /// Pixels stretched onto the tile instead of `content`, when set.
    std::shared_ptr<const RasterImage> image;
    bool repeat = true; ///< tiles the plane; otherwise drawn once, edges extended
    bool smooth = true; ///< bilinear sampling; nearest pixel otherwise (image-rendering)
};

/// What gets drawn: a size and a tree of groups and shapes.
struct Scene {
    double width = 0, height = 0; ///< device size at scale 1, in px
    Group root;
};

} // namespace casteljau
