// Drawing: the library's retained, editable shape list (render/drawing.h).
//
// The Python object owns the Drawing and a mutex. Rendering releases the GIL
// (so threads render in parallel), and every method takes the mutex, always
// after releasing the GIL: a thread holding the mutex never waits for the
// GIL while another waits for the mutex with the GIL held, so there is no
// deadlock, and an edit from one thread cannot race a render in another.
#include "casteljau/render/drawing.h"

#include "common.h"

#include <cmath>
#include <memory>
#include <mutex>

namespace casteljau::python {

namespace {

using namespace pybind11::literals;

struct PyDrawing {
    PyDrawing(int w, int h) : drawing(w, h) {}
    Drawing drawing;
    std::mutex mutex;
};

// Locks the drawing's mutex with the GIL released while waiting.
std::unique_lock<std::mutex> lock(PyDrawing& d) {
    std::unique_lock<std::mutex> l(d.mutex, std::defer_lock);
    py::gil_scoped_release release;
    l.lock();
    return l;
}

Affine checked_transform(const std::optional<Affine>& t) {
    const Affine m = t.value_or(Affine::identity());
    if (!m.is_finite() || m.determinant() == 0 || !std::isfinite(m.determinant()) ||
        !m.inverse().is_finite())
        value_error("transform: must be finite and invertible");
    return m;
}

py::tuple rect(const PixelRect& r) { return py::make_tuple(r.x0, r.y0, r.x1, r.y1); }

Drawing::ShapeId checked_id(const Drawing& d, py::ssize_t id) {
    if (id < 0 || std::size_t(id) >= d.size())
        throw py::index_error("shape id " + std::to_string(id) + " is not in the drawing (0 to " +
                              std::to_string(d.size()) + ")");
    return Drawing::ShapeId(id);
}

RenderOptions render_options(double tolerance, const std::string& method,
                             std::optional<int> segments, bool antialias) {
    RenderOptions o;
    o.flatten = flatten_options(tolerance, method, segments);
    o.antialias = antialias;
    return o;
}

template <class C>
C* canvas_of(PyDrawing& d, py::handle h) {
    C* c = h.cast<C*>();
    if (c->width() != d.drawing.width() || c->height() != d.drawing.height())
        value_error("canvas: " + std::to_string(c->width()) + " x " + std::to_string(c->height()) +
                    ", the drawing is " + std::to_string(d.drawing.width()) + " x " +
                    std::to_string(d.drawing.height()));
    return c;
}

// Calls f(canvas) with the Canvas or Canvas8 that `h` holds.
template <class F>
void with_canvas(PyDrawing& d, py::handle h, F&& f) {
    if (py::isinstance<Canvas>(h))
        f(*canvas_of<Canvas>(d, h));
    else if (py::isinstance<Canvas8>(h))
        f(*canvas_of<Canvas8>(d, h));
    else
        throw py::type_error("canvas: expected a casteljau.Canvas or Canvas8");
}

PixelRect to_pixel_rect(const py::sequence& r) {
    if (py::len(r) != 4) value_error("dirty: expected (x0, y0, x1, y1)");
    return {r[0].cast<int>(), r[1].cast<int>(), r[2].cast<int>(), r[3].cast<int>()};
}

} // namespace

void bind_drawing(py::module_& m) {
    py::class_<PyDrawing>(m, "Drawing", R"doc(
A retained, editable list of shapes on a width x height pixel canvas, for
applications that change a drawing shape by shape and redraw only what
changed.

fill() and stroke() add shapes and return their ids (stable for the
drawing's life); replace() and remove() change one and return the dirty
rectangle (x0, y0, x1, y1) in pixels (empty when x1 <= x0 or y1 <= y0);
render_region(canvas, dirty) then redraws just those pixels, leaving the
canvas bit-identical to a full render() of the edited drawing. shape_at()
and shapes_in() hit-test exactly on the curves. Transforms map path
coordinates to pixels and must be invertible. Rendering releases the GIL;
methods are safe to call from several threads.)doc")
        .def(py::init([](int width, int height) {
                 check_canvas_size(width, height);
                 return std::make_unique<PyDrawing>(width, height);
             }),
             "width"_a, "height"_a, "An empty drawing whose device space is the canvas's pixels.")
        .def_property_readonly(
            "width", [](PyDrawing& d) { return d.drawing.width(); }, "Canvas width in pixels.")
        .def_property_readonly(
            "height", [](PyDrawing& d) { return d.drawing.height(); }, "Canvas height in pixels.")
        .def(
            "__len__",
            [](PyDrawing& d) {
                auto l = lock(d);
                return d.drawing.size();
            },
            "Number of shapes, removed ones included (ids run from 0 to len - 1).")
        .def(
            "fill",
            [](PyDrawing& d, const Path& path, const Paint& paint, std::optional<Affine> transform,
               const std::string& rule) {
                const Affine t = checked_transform(transform);
                const FillRule r = to_rule(rule);
                auto l = lock(d);
                return d.drawing.fill(path, paint, t, r);
            },
            "path"_a, "paint"_a, "transform"_a = py::none(), py::kw_only(), "rule"_a = "nonzero",
            "Adds a filled path (mapped to pixels by `transform`, default the identity; `rule` "
            "'nonzero' or 'evenodd'); returns its id.")
        .def(
            "stroke",
            [](PyDrawing& d, const Path& path, const Paint& paint,
               std::optional<StrokeGeometry> geometry, std::optional<Affine> transform) {
                const Affine t = checked_transform(transform);
                auto l = lock(d);
                return d.drawing.stroke(path, paint, geometry.value_or(StrokeGeometry{}), t);
            },
            "path"_a, "paint"_a, "geometry"_a = py::none(), "transform"_a = py::none(),
            "Adds a stroked path (StrokeGeometry, default width 1; the width is in path "
            "coordinates); returns its id.")
        .def(
            "replace",
            [](PyDrawing& d, py::ssize_t id, std::optional<Path> path, std::optional<Paint> paint,
               std::optional<Affine> transform, std::optional<StrokeGeometry> geometry,
               std::optional<std::string> rule) {
                const std::optional<Affine> t =
                    transform ? std::optional<Affine>(checked_transform(transform)) : std::nullopt;
                // (A plain value and a flag: GCC 12 takes an optional<FillRule> for
                // maybe-uninitialized here.)
                const bool has_rule = rule.has_value();
                const FillRule fill_rule = has_rule ? to_rule(*rule) : FillRule::NonZero;
                auto l = lock(d);
                Shape s = d.drawing.shape(checked_id(d.drawing, id));
                if (geometry && !s.stroke)
                    value_error("geometry: shape " + std::to_string(id) + " is not a stroke");
                if (has_rule && !s.fill)
                    value_error("rule: shape " + std::to_string(id) + " is not a fill");
                if (paint && !s.fill && !s.stroke)
                    value_error("paint: shape " + std::to_string(id) + " was removed");
                if (path) s.path = *path;
                if (t) s.transform = *t;
                if (has_rule) s.fill->rule = fill_rule;
                if (geometry) s.stroke->geometry = *geometry;
                if (paint && s.fill) {
                    s.fill->color = paint->color;
                    s.fill->gradient = paint->gradient;
                    s.fill->opacity = paint->opacity;
                } else if (paint) {
                    s.stroke->color = paint->color;
                    s.stroke->gradient = paint->gradient;
                    s.stroke->opacity = paint->opacity;
                }
                return rect(d.drawing.replace(Drawing::ShapeId(id), std::move(s)));
            },
            "id"_a, py::kw_only(), "path"_a = py::none(), "paint"_a = py::none(),
            "transform"_a = py::none(), "geometry"_a = py::none(), "rule"_a = py::none(),
            "Changes shape `id`: whatever is given replaces the shape's own (geometry only for "
            "a stroke, rule only for a fill). Returns the dirty rectangle (x0, y0, x1, y1).")
        .def(
            "remove",
            [](PyDrawing& d, py::ssize_t id) {
                auto l = lock(d);
                return rect(d.drawing.remove(checked_id(d.drawing, id)));
            },
            "id"_a, "Removes shape `id` (its id is not reused); returns the dirty rectangle.")
        .def(
            "damage",
            [](PyDrawing& d, py::ssize_t id) {
                auto l = lock(d);
                return rect(d.drawing.damage(checked_id(d.drawing, id)));
            },
            "id"_a, "The pixels shape `id` can change, (x0, y0, x1, y1), clipped to the canvas.")
        .def(
            "render",
            [](PyDrawing& d, py::object canvas, py::object background, double tolerance,
               const std::string& method, std::optional<int> segments, bool antialias,
               int threads) {
                const Premul bg = to_background(background);
                const RenderOptions o = render_options(tolerance, method, segments, antialias);
                const int n = resolve_threads(threads);
                if (canvas.is_none())
                    canvas = py::type::of<Canvas>()(d.drawing.width(), d.drawing.height());
                with_canvas(d, canvas, [&](auto& c) {
                    auto l = lock(d);
                    py::gil_scoped_release release;
                    d.drawing.render(c, bg, o, n);
                });
                return canvas;
            },
            "canvas"_a = py::none(), py::kw_only(), "background"_a = py::none(),
            "tolerance"_a = 0.25, "method"_a = "guided", "segments"_a = py::none(),
            "antialias"_a = true, "threads"_a = 1,
            "Renders every shape onto `canvas` (a Canvas or Canvas8 of the drawing's size; "
            "None: a new Canvas) over `background`; returns the canvas. The GIL is released.")
        .def(
            "render_region",
            [](PyDrawing& d, py::object canvas, const py::sequence& dirty, py::object background,
               double tolerance, const std::string& method, std::optional<int> segments,
               bool antialias) {
                const Premul bg = to_background(background);
                const RenderOptions o = render_options(tolerance, method, segments, antialias);
                const PixelRect r = to_pixel_rect(dirty);
                with_canvas(d, canvas, [&](auto& c) {
                    auto l = lock(d);
                    py::gil_scoped_release release;
                    d.drawing.render_region(c, r, bg, o);
                });
                return canvas;
            },
            "canvas"_a, "dirty"_a, py::kw_only(), "background"_a = py::none(), "tolerance"_a = 0.25,
            "method"_a = "guided", "segments"_a = py::none(), "antialias"_a = true,
            "Re-renders only the rectangle `dirty` (x0, y0, x1, y1; clipped to the canvas) of "
            "a canvas rendered before, with the same options: the result equals a full render.")
        .def(
            "shape_at",
            [](PyDrawing& d, double x, double y, double tolerance) -> py::object {
                const Point p{finite(x, "x"), finite(y, "y")};
                if (!(tolerance >= 0) || !std::isfinite(tolerance))
                    value_error("tolerance must be finite and >= 0");
                std::optional<Drawing::ShapeId> hit;
                {
                    auto l = lock(d);
                    py::gil_scoped_release release;
                    hit = d.drawing.shape_at(p, tolerance);
                }
                if (!hit) return py::none();
                return py::int_(*hit);
            },
            "x"_a, "y"_a, "tolerance"_a = 0.5,
            "The topmost shape whose fill holds pixel point (x, y) or whose stroke lies within "
            "`tolerance` px of it; None over empty canvas.")
        .def(
            "shapes_in",
            [](PyDrawing& d, double x0, double y0, double x1, double y1) {
                const Rect r = Rect::from_points({finite(x0, "x0"), finite(y0, "y0")},
                                                 {finite(x1, "x1"), finite(y1, "y1")});
                std::vector<Drawing::ShapeId> hits;
                {
                    auto l = lock(d);
                    py::gil_scoped_release release;
                    hits = d.drawing.shapes_in(r);
                }
                return hits;
            },
            "x0"_a, "y0"_a, "x1"_a, "y1"_a,
            "Ids of the shapes whose fill or stroke meets the rectangle (pixels), in drawing "
            "order: rubber-band selection.")
        .def("__repr__", [](PyDrawing& d) {
            return "<casteljau.Drawing " + std::to_string(d.drawing.width()) + " x " +
                   std::to_string(d.drawing.height()) + ", " + std::to_string(d.drawing.size()) +
                   " shapes>";
        });
}

} // namespace casteljau::python
