// Hit tests on a Path, exact on its curves (lib/casteljau/hit, not on a
// flattening): point in fill and winding number, nearest point, rectangle
// against fill or outline; and on its stroke, to a tolerance: distance and
// bounds. contains() and winding() take a point (x, y) or an
// (N, 2) array of points, answered by a value or an array of N; an array is
// answered on a copy of the path with the GIL released, so that another
// thread may go on (and even edit the path) meanwhile.
#include "casteljau/hit/nearest.h"
#include "casteljau/hit/rect_hit.h"
#include "casteljau/hit/stroke_hit.h"
#include "casteljau/hit/winding.h"
#include "common.h"

namespace casteljau::python {

namespace {

using namespace pybind11::literals;

using PointArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// f(path, p) for one point, or for each row of an (N, 2) array into an array of T.
template <class T, class F>
py::object per_point(const Path& path, py::handle points, F&& f) {
    const PointArray in = PointArray::ensure(points);
    if (!in) throw py::type_error("expected a point (x, y) or an (N, 2) array of points");
    if (in.ndim() == 1 && in.shape(0) == 2)
        return py::cast(T(f(path, Point{finite(in.at(0), "x"), finite(in.at(1), "y")})));
    if (in.ndim() != 2 || in.shape(1) != 2)
        value_error("expected a point (x, y) or an (N, 2) array of points, not shape " +
                    py::str(py::handle(in).attr("shape")).cast<std::string>());
    const auto r = in.unchecked<2>();
    const py::ssize_t n = in.shape(0);
    for (py::ssize_t i = 0; i < n; ++i)
        if (!std::isfinite(r(i, 0)) || !std::isfinite(r(i, 1)))
            value_error("points[" + std::to_string(i) + "] is not finite");
    py::array_t<T> out(n);
    auto o = out.template mutable_unchecked<1>();
    const Path copy = path;
    {
        py::gil_scoped_release release;
        for (py::ssize_t i = 0; i < n; ++i) o(i) = T(f(copy, Point{r(i, 0), r(i, 1)}));
    }
    return out;
}

// The stroke hit tests' tolerance: finite and at least 1e-6 (the stroker
// bounds its work for any, but finer answers are rounding noise on a
// drawing's coordinates).
double stroke_tolerance(double tolerance) {
    if (!(tolerance >= 1e-6) || !std::isfinite(tolerance))
        value_error("tolerance must be finite and >= 1e-6");
    return tolerance;
}

} // namespace

void bind_hit(py::module_& m) {
    auto path = py::reinterpret_borrow<py::class_<Path>>(m.attr("Path"));
    path.def(
            "contains",
            [](const Path& p, py::handle points, const std::string& rule) {
                const FillRule r = to_rule(rule);
                return per_point<bool>(
                    p, points, [r](const Path& q, Point x) { return fill_contains(q, x, r); });
            },
            "points"_a, "rule"_a = "nonzero",
            "Whether the point (x, y) lies in the path's fill under `rule` ('nonzero' or "
            "'evenodd'; open subpaths are closed, as for drawing), exactly on the curves; for an "
            "(N, 2) array of points, a bool array of N.")
        .def(
            "winding",
            [](const Path& p, py::handle points) {
                return per_point<int>(p, points, winding_number);
            },
            "points"_a,
            "The winding number of the fill's outline around the point (x, y), or an int array "
            "for an (N, 2) array of points.")
        .def(
            "nearest",
            [](const Path& p, double x, double y) -> py::object {
                const PathNearestPoint n = nearest_point(p, {finite(x, "x"), finite(y, "y")});
                if (!std::isfinite(n.nearest.distance)) return py::none();
                std::size_t index = n.segment; // into Path.segments, over all subpaths
                for (std::size_t i = 0; i < n.subpath; ++i)
                    index += p.subpaths()[i].segments.size();
                return py::make_tuple(n.nearest.distance,
                                      py::make_tuple(n.nearest.point.x, n.nearest.point.y), index,
                                      n.nearest.t);
            },
            "x"_a, "y"_a,
            "The point of the path's curves nearest to (x, y), exactly: (distance, (px, py), "
            "index, t), with index the segment's in `segments` and t its curve parameter; None "
            "for a path without segments.")
        .def(
            "intersects_rect",
            [](const Path& p, double x0, double y0, double x1, double y1, bool fill,
               const std::string& rule) {
                const Rect r = Rect::from_points({finite(x0, "x0"), finite(y0, "y0")},
                                                 {finite(x1, "x1"), finite(y1, "y1")});
                return fill ? fill_intersects_rect(p, r, to_rule(rule))
                            : outline_intersects_rect(p, r);
            },
            "x0"_a, "y0"_a, "x1"_a, "y1"_a, py::kw_only(), "fill"_a = true, "rule"_a = "nonzero",
            "Whether the rectangle meets the path's fill under `rule` (fill=True: a rectangle "
            "wholly inside counts), or its curves (fill=False), exactly.")
        .def(
            "stroke_distance",
            [](const Path& p, double x, double y, const StrokeGeometry& geometry,
               double tolerance) {
                const Point q{finite(x, "x"), finite(y, "y")};
                const double tol = stroke_tolerance(tolerance);
                // Copies: the outline takes a while, and other threads go on
                // (and may change the path or the geometry) meanwhile.
                const Path path = p;
                const StrokeGeometry g = geometry;
                py::gil_scoped_release release;
                return stroke_distance(path, g, q, tol);
            },
            "x"_a, "y"_a, "geometry"_a, "tolerance"_a = 1e-3,
            "Distance from (x, y) to the path's stroke as drawn with `geometry` (a "
            "StrokeGeometry: width, caps, joins, dashes), 0 inside it, within `tolerance`.")
        .def(
            "stroke_bounds",
            [](const Path& p, const StrokeGeometry& geometry, double tolerance) {
                const double tol = stroke_tolerance(tolerance);
                const Path path = p; // as in stroke_distance
                const StrokeGeometry g = geometry;
                Rect box;
                {
                    py::gil_scoped_release release;
                    box = stroke_bounds(path, g, tol);
                }
                return rect_tuple(box);
            },
            "geometry"_a, "tolerance"_a = 1e-3,
            "A box (x0, y0, x1, y1) holding the stroke drawn with `geometry`, at most "
            "`tolerance` larger than its tight bounds; None when nothing is drawn.");
}

} // namespace casteljau::python
