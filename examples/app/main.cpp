// What a drawing application does with Casteljau: build a path, fill and
// stroke it with paints and transforms, save the image; then edit a shape
// through its handles, hit-test it, and redraw only what changed.
//
// Usage: casteljau_app OUT.png
#include <casteljau/casteljau.h>
#include <cstdio>

using namespace casteljau;

int main(int argc, char** argv) {
    if (argc != 2) return std::fprintf(stderr, "usage: %s OUT.png\n", argv[0]), 2;

    // A heart, filled with a gradient and outlined; a smaller copy, turned.
    Path heart;
    heart.move_to({0, 80});
    heart.cubic_to({-120, 0}, {-60, -90}, {0, -30});
    heart.cubic_to({60, -90}, {120, 0}, {0, 80});
    heart.close();
    Drawing drawing(480, 320);
    const Paint red =
        Paint::linear({0, -60}, {0, 80}, {{0, {1, 0.4f, 0.5f, 1}}, {1, {0.7f, 0, 0.1f, 1}}});
    drawing.fill(heart, red, Affine::translate({170, 150}));
    StrokeGeometry outline;
    outline.width = 6;
    outline.join = LineJoin::Round;
    drawing.stroke(heart, Paint::solid({0.3f, 0, 0.05f, 1}), outline,
                   Affine::translate({170, 150}));
    const auto small =
        drawing.fill(heart, Paint::solid({0.2f, 0.3f, 0.8f, 0.8f}),
                     Affine::translate({370, 180}) * Affine::rotate(0.4) * Affine::scale(0.6, 0.6));
    Canvas canvas(drawing.width(), drawing.height());
    const Premul white = premultiply({1, 1, 1, 1});
    drawing.render(canvas, white);

    // Edit: drag the small heart's bottom anchor; its handles come along.
    BezierSpline spline = BezierSpline::from_subpath(heart.subpaths()[0]);
    spline.move_anchor(0, {0, 110});
    Path edited;
    edited.add_subpath(spline.to_subpath());
    Shape moved = drawing.shape(small);
    moved.path = edited;
    const PixelRect dirty = drawing.replace(small, moved);
    drawing.render_region(canvas, dirty, white);

    // Hit-test in the heart's own coordinates.
    const bool inside = fill_contains(heart, {0, 0});
    const PathNearestPoint near = nearest_point(heart, {100, 100});
    std::printf("redrew %dx%d px; (0,0) inside: %d; nearest to (100,100): segment %zu t=%.3f\n",
                dirty.width(), dirty.height(), inside, near.segment, near.nearest.t);

    const std::string error = write_canvas_atomic(argv[1], canvas);
    if (!error.empty()) return std::fprintf(stderr, "%s\n", error.c_str()), 1;
    return 0;
}
