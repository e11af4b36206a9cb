// Scene: what gets drawn, independent of where it came from (the SVG reader
// builds one; an application can build one directly).
//
// A scene is a tree of groups and shapes. Each shape carries its path in user
// space, the full transform from user space to the scene's device space (the
// product of its ancestors' transforms, its own and the viewBox mapping), and
// its paint. A group carries only its opacity: group opacity needs an
// offscreen layer, so groups with opacity 1 are flattened away by builders.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/paint/color.h"
#include "casteljau/paint/gradient.h"
#include "casteljau/raster/sweep.h"

#include <memory>
#include <optional>
#include <variant>
#include <vector>

namespace casteljau {

/// How a shape is filled: paint, opacity and fill rule.
struct Fill {
    Rgba color;                               ///< used when there is no gradient
    std::shared_ptr<const Gradient> gradient; ///< shared by every shape that uses it
    float opacity = 1;                        ///< fill-opacity
    FillRule rule = FillRule::NonZero;
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
    Rgba color;                               ///< used when there is no gradient
    std::shared_ptr<const Gradient> gradient; ///< shared by every shape that uses it
    float opacity = 1;
    StrokeGeometry geometry;
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

/// Children drawn together, composited with the group's opacity.
struct Group {
    float opacity = 1;
    std::vector<Node> children;
};

/// A shape or a group.
struct Node {
    std::variant<Shape, Group> item;
};

/// What gets drawn: a size and a tree of groups and shapes.
struct Scene {
    double width = 0, height = 0; ///< device size at scale 1, in px
    Group root;
};

} // namespace casteljau
