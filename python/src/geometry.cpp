// Affine and Path: the geometry values of the package.
//
// Points cross the boundary as (x, y) tuples, point lists as (N, 2) float64
// arrays. A Path's array form (Path.to_numpy / Path.from_numpy) is three
// arrays: verbs (uint8, one per command), points (N x 2 float64, the points
// the verbs consume in order: MOVE 1, LINE 1, QUAD 2, CUBIC 3, CONIC 2,
// CLOSE 0) and weights (float64, one per CONIC). Every subpath is written as
// MOVE, its segments, and CLOSE when closed (the closing line, which close()
// adds to a subpath that does not end at its start, is written as a LINE), so
// that from_numpy(to_numpy(p)) == p exactly.
#include "casteljau/curve/path.h"
#include "casteljau/curve/path_data.h"
#include "common.h"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <vector>

namespace casteljau::python {

namespace {

using namespace pybind11::literals;

enum Verb : std::uint8_t { kMove = 0, kLine = 1, kQuad = 2, kCubic = 3, kConic = 4, kClose = 5 };
constexpr int kVerbPoints[] = {1, 1, 2, 3, 2, 0};

using PointArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// An (N, 2) float64 array of points (N may be 0).
PointArray as_points(py::handle h, const char* what) {
    PointArray a = PointArray::ensure(h);
    if (!a) throw py::type_error(std::string(what) + ": expected an (N, 2) array of numbers");
    if (a.ndim() == 1 && a.shape(0) == 0) return PointArray(std::vector<py::ssize_t>{0, 2});
    if (a.ndim() != 2 || a.shape(1) != 2)
        value_error(std::string(what) + ": expected an (N, 2) array, not shape " +
                    py::str(py::handle(a).attr("shape")).cast<std::string>());
    return a;
}

PointArray new_points(std::size_t n) {
    return PointArray(std::vector<py::ssize_t>{py::ssize_t(n), 2});
}

py::tuple xy(Point p) { return py::make_tuple(p.x, p.y); }

std::string affine_repr(const Affine& m) {
    std::ostringstream s;
    s.precision(17);
    s << "Affine(" << m.a << ", " << m.b << ", " << m.c << ", " << m.d << ", " << m.e << ", " << m.f
      << ")";
    return s.str();
}

// Maps a point (x, y) or an (N, 2) array of points.
py::object apply_affine(const Affine& m, py::handle points) {
    const PointArray in = PointArray::ensure(points);
    if (!in) throw py::type_error("expected a point (x, y) or an (N, 2) array of points");
    if (in.ndim() == 1 && in.shape(0) == 2) return xy(m * Point{in.at(0), in.at(1)});
    const PointArray a = as_points(in, "points");
    PointArray out = new_points(std::size_t(a.shape(0)));
    const auto src = a.unchecked<2>();
    auto dst = out.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < a.shape(0); ++i) {
        const Point p = m * Point{src(i, 0), src(i, 1)};
        dst(i, 0) = p.x;
        dst(i, 1) = p.y;
    }
    return out;
}

double angle(double a, bool degrees) {
    return finite(degrees ? degrees_to_radians(a) : a, "angle");
}

// --- Path -------------------------------------------------------------------

const char* kind_name(const Segment& s) {
    switch (s.index()) {
    case 0:
        return "line";
    case 1:
        return "quad";
    case 2:
        return "cubic";
    default:
        return "conic";
    }
}

std::vector<Point> control_points(const Segment& s) {
    return std::visit(
        [](const auto& c) {
            const auto pts = [&] {
                if constexpr (requires { c.p; })
                    return std::vector<Point>(c.p.begin(), c.p.end());
                else
                    return std::vector<Point>{c.p0, c.p1, c.p2};
            }();
            return pts;
        },
        s);
}

py::tuple path_arrays(const Path& path) {
    std::vector<std::uint8_t> verbs;
    std::vector<Point> points;
    std::vector<double> weights;
    for (const Subpath& sp : path.subpaths()) {
        verbs.push_back(kMove);
        points.push_back(sp.start);
        for (const Segment& s : sp.segments) {
            verbs.push_back(std::uint8_t(s.index() + 1));
            const std::vector<Point> c = control_points(s);
            points.insert(points.end(), c.begin() + 1, c.end());
            if (const Conic* k = std::get_if<Conic>(&s)) weights.push_back(k->w);
        }
        if (sp.closed) verbs.push_back(kClose);
    }
    py::array_t<std::uint8_t> v(py::ssize_t(verbs.size()));
    std::copy(verbs.begin(), verbs.end(), v.mutable_data());
    PointArray p = new_points(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        p.mutable_data()[2 * i] = points[i].x;
        p.mutable_data()[2 * i + 1] = points[i].y;
    }
    py::array_t<double> w(py::ssize_t(weights.size()));
    std::copy(weights.begin(), weights.end(), w.mutable_data());
    return py::module_::import("casteljau._casteljau").attr("PathArrays")(v, p, w);
}

Path path_from_arrays(py::handle verbs_in, py::handle points_in, py::handle weights_in) {
    const auto verbs =
        py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(verbs_in);
    if (!verbs || verbs.ndim() != 1) value_error("verbs: expected a 1-D array of verb codes");
    const PointArray points = as_points(points_in, "points");
    py::array_t<double, py::array::c_style | py::array::forcecast> weights;
    if (!weights_in.is_none()) {
        weights =
            py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(weights_in);
        if (!weights || weights.ndim() != 1) value_error("weights: expected a 1-D array");
    }
    const auto v = verbs.unchecked<1>();
    const auto p = points.unchecked<2>();
    const py::ssize_t n_weights = weights ? weights.shape(0) : 0;
    py::ssize_t needed = 0, conics = 0;
    for (py::ssize_t i = 0; i < verbs.shape(0); ++i) {
        if (v(i) < 0 || v(i) > kClose)
            value_error("verbs[" + std::to_string(i) + "]: " + std::to_string(v(i)) +
                        " is not a verb (MOVE 0, LINE 1, QUAD 2, CUBIC 3, CONIC 4, CLOSE 5)");
        needed += kVerbPoints[v(i)];
        conics += v(i) == kConic;
    }
    if (needed != points.shape(0))
        value_error("points: the verbs take " + std::to_string(needed) + " points, not " +
                    std::to_string(points.shape(0)));
    if (conics != n_weights)
        value_error("weights: the verbs have " + std::to_string(conics) + " conics, not " +
                    std::to_string(n_weights) + " weights");
    Path path;
    py::ssize_t k = 0, c = 0;
    const auto pt = [&] {
        const Point q{finite(p(k, 0), "points"), finite(p(k, 1), "points")};
        ++k;
        return q;
    };
    for (py::ssize_t i = 0; i < verbs.shape(0); ++i) {
        switch (v(i)) {
        case kMove:
            path.move_to(pt());
            break;
        case kLine:
            path.line_to(pt());
            break;
        case kQuad: {
            const Point a = pt();
            path.quad_to(a, pt());
            break;
        }
        case kCubic: {
            const Point a = pt(), b = pt();
            path.cubic_to(a, b, pt());
            break;
        }
        case kConic: {
            const double w = weights.at(c++);
            if (!(w > 0) || !std::isfinite(w)) value_error("weights: a conic's weight must be > 0");
            const Point a = pt();
            path.conic_to(a, pt(), w);
            break;
        }
        default:
            path.close();
        }
    }
    return path;
}

bool same_path(const Path& a, const Path& b) {
    const auto& x = a.subpaths();
    const auto& y = b.subpaths();
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (!(x[i].start == y[i].start && x[i].closed == y[i].closed &&
              x[i].segments == y[i].segments))
            return false;
    return true;
}

Path parse_d(const std::string& d, bool strict) {
    PathDataResult r = parse_path_data(d);
    if (r.error && strict)
        value_error("path data: at offset " + std::to_string(r.error->offset) + ": " +
                    r.error->message);
    return std::move(r.path);
}

} // namespace

void bind_geometry(py::module_& m) {
    m.attr("PathArrays") =
        py::module_::import("collections")
            .attr("namedtuple")("PathArrays", "verbs points weights", "module"_a = "casteljau");
    m.attr("PathArrays").attr("__doc__") =
        "A Path as arrays: verbs (uint8, one per command: MOVE 0, LINE 1, QUAD 2, CUBIC 3, "
        "CONIC 4, CLOSE 5), points ((N, 2) float64, consumed in order: MOVE 1, LINE 1, "
        "QUAD 2, CUBIC 3, CONIC 2, CLOSE 0) and weights (float64, one per CONIC).";
    m.attr("MOVE") = int(kMove);
    m.attr("LINE") = int(kLine);
    m.attr("QUAD") = int(kQuad);
    m.attr("CUBIC") = int(kCubic);
    m.attr("CONIC") = int(kConic);
    m.attr("CLOSE") = int(kClose);

    py::class_<Affine>(m, "Affine", R"doc(
A 2D affine map in SVG's matrix(a b c d e f) order:
x' = a x + c y + e,  y' = b x + d y + f.

Compose with ``@`` (or ``*``): ``(A @ B).apply(p) == A.apply(B.apply(p))``,
B first, as in the maths. ``apply`` maps a point ``(x, y)`` to a tuple and
an (N, 2) array to a new (N, 2) float64 array. Affines are immutable values
(hashable, comparable, picklable).)doc")
        .def(py::init([](double a, double b, double c, double d, double e, double f) {
                 return Affine{finite(a, "a"), finite(b, "b"), finite(c, "c"),
                               finite(d, "d"), finite(e, "e"), finite(f, "f")};
             }),
             "a"_a = 1.0, "b"_a = 0.0, "c"_a = 0.0, "d"_a = 1.0, "e"_a = 0.0, "f"_a = 0.0,
             "The map x' = a x + c y + e, y' = b x + d y + f (default: the identity).")
        .def_static("identity", &Affine::identity, "The identity map.")
        .def_static(
            "translate",
            [](double tx, double ty) {
                return Affine::translate({finite(tx, "tx"), finite(ty, "ty")});
            },
            "tx"_a, "ty"_a = 0.0, "Translation by (tx, ty).")
        .def_static(
            "scale",
            [](double sx, std::optional<double> sy) {
                return Affine::scale(finite(sx, "sx"), finite(sy.value_or(sx), "sy"));
            },
            "sx"_a, "sy"_a = py::none(), "Scaling by sx along x and sy (default sx) along y.")
        .def_static(
            "rotate", [](double a, bool degrees) { return Affine::rotate(angle(a, degrees)); },
            "angle"_a, py::kw_only(), "degrees"_a = false,
            "Rotation by `angle` radians (or degrees with degrees=True), from +x towards +y.")
        .def_static(
            "skew_x", [](double a, bool degrees) { return Affine::skew_x(angle(a, degrees)); },
            "angle"_a, py::kw_only(), "degrees"_a = false, "SVG's skewX(angle).")
        .def_static(
            "skew_y", [](double a, bool degrees) { return Affine::skew_y(angle(a, degrees)); },
            "angle"_a, py::kw_only(), "degrees"_a = false, "SVG's skewY(angle).")
        .def_static(
            "from_numpy",
            [](py::array_t<double, py::array::c_style | py::array::forcecast> a) {
                if (a.ndim() != 2 || !((a.shape(0) == 3 || a.shape(0) == 2) && a.shape(1) == 3))
                    value_error("expected a 2x3 or 3x3 matrix");
                const auto r = a.unchecked<2>();
                if (a.shape(0) == 3 && !(r(2, 0) == 0 && r(2, 1) == 0 && r(2, 2) == 1))
                    value_error("the last row of an affine matrix is (0, 0, 1)");
                return Affine{finite(r(0, 0), "a"), finite(r(1, 0), "b"), finite(r(0, 1), "c"),
                              finite(r(1, 1), "d"), finite(r(0, 2), "e"), finite(r(1, 2), "f")};
            },
            "matrix"_a, "From a 3x3 (or 2x3) matrix [[a, c, e], [b, d, f], [0, 0, 1]].")
        .def(
            "to_numpy",
            [](const Affine& t) {
                py::array_t<double> out({3, 3});
                double* d = out.mutable_data();
                const double v[9] = {t.a, t.c, t.e, t.b, t.d, t.f, 0, 0, 1};
                std::copy(v, v + 9, d);
                return out;
            },
            "The 3x3 matrix [[a, c, e], [b, d, f], [0, 0, 1]] (float64).")
        .def_property_readonly(
            "a", [](const Affine& t) { return t.a; }, "Coefficient a.")
        .def_property_readonly(
            "b", [](const Affine& t) { return t.b; }, "Coefficient b.")
        .def_property_readonly(
            "c", [](const Affine& t) { return t.c; }, "Coefficient c.")
        .def_property_readonly(
            "d", [](const Affine& t) { return t.d; }, "Coefficient d.")
        .def_property_readonly(
            "e", [](const Affine& t) { return t.e; }, "Coefficient e.")
        .def_property_readonly(
            "f", [](const Affine& t) { return t.f; }, "Coefficient f.")
        .def_property_readonly(
            "coefficients",
            [](const Affine& t) { return py::make_tuple(t.a, t.b, t.c, t.d, t.e, t.f); },
            "(a, b, c, d, e, f).")
        .def("determinant", &Affine::determinant,
             "Determinant of the linear part (negative when the map mirrors).")
        .def(
            "inverse",
            [](const Affine& t) {
                const double det = t.determinant();
                if (det == 0 || !std::isfinite(det)) value_error("the affine map is singular");
                const Affine inv = t.inverse();
                if (!inv.is_finite()) value_error("the affine map is singular");
                return inv;
            },
            "The inverse map; ValueError when the map is singular.")
        .def("apply", &apply_affine, "points"_a,
             "Maps a point (x, y) (returns a tuple) or an (N, 2) array of points (returns a new "
             "(N, 2) float64 array).")
        .def("__call__", &apply_affine, "points"_a, "Same as apply().")
        .def(
            "__matmul__", [](const Affine& x, const Affine& y) { return x * y; },
            "Composition: (A @ B) applies B first, then A.")
        .def(
            "__mul__", [](const Affine& x, const Affine& y) { return x * y; }, "Composition, as @.")
        .def(
            "__eq__", [](const Affine& x, const Affine& y) { return x == y; }, "Exact equality.")
        .def(
            "__ne__", [](const Affine& x, const Affine& y) { return !(x == y); }, "Inequality.")
        .def(
            "__hash__",
            [](const Affine& t) { return py::hash(py::make_tuple(t.a, t.b, t.c, t.d, t.e, t.f)); },
            "Hash of the coefficients.")
        .def("__repr__", &affine_repr, "Affine(a, b, c, d, e, f).")
        .def(py::pickle(
            [](const Affine& t) { return py::make_tuple(t.a, t.b, t.c, t.d, t.e, t.f); },
            [](const py::tuple& s) {
                if (py::len(s) != 6) value_error("Affine state: 6 coefficients");
                return Affine{s[0].cast<double>(), s[1].cast<double>(), s[2].cast<double>(),
                              s[3].cast<double>(), s[4].cast<double>(), s[5].cast<double>()};
            }));

    py::class_<Path>(m, "Path", R"doc(
A 2D path: subpaths of lines, quadratic and cubic Beziers and conics.

Build it like a canvas path (every method returns the path, so calls chain)::

    p = Path().move_to(0, 0).cubic_to(50, 100, 150, -100, 200, 0).close()

or from SVG path data with Path.from_svg_d(d), or from arrays with
Path.from_numpy(verbs, points, weights). Path.to_numpy() gives the array
form back (a PathArrays named tuple): verbs (uint8: MOVE 0, LINE 1, QUAD 2,
CUBIC 3, CONIC 4, CLOSE 5), points ((N, 2) float64, the points each verb
takes in order: MOVE 1, LINE 1, QUAD 2, CUBIC 3, CONIC 2, CLOSE 0), weights
(float64, one per CONIC). Every subpath starts with a MOVE; the round trip is
exact. len(path) is the number of segments; coordinates must be finite.)doc")
        .def(py::init<>(), "An empty path.")
        .def_static("from_svg_d", &parse_d, "d"_a, py::kw_only(), "strict"_a = true,
                    "Parses SVG path data. With strict=True (the default) an error raises "
                    "ValueError('path data: at offset N: what'); with strict=False the path is "
                    "the data up to its first error, as SVG renders it.")
        .def_static("from_numpy", &path_from_arrays, "verbs"_a, "points"_a,
                    "weights"_a = py::none(),
                    "A path from its array form (see the class doc and to_numpy); ValueError "
                    "when the counts disagree or a value is not finite.")
        .def("to_numpy", &path_arrays,
             "The array form: PathArrays(verbs uint8 (K,), points float64 (N, 2), weights "
             "float64 (C,)).")
        .def(
            "move_to",
            [](Path& p, double x, double y) -> Path& {
                p.move_to({finite(x, "x"), finite(y, "y")});
                return p;
            },
            "x"_a, "y"_a, "Starts a new subpath at (x, y).",
            py::return_value_policy::reference_internal)
        .def(
            "line_to",
            [](Path& p, double x, double y) -> Path& {
                p.line_to({finite(x, "x"), finite(y, "y")});
                return p;
            },
            "x"_a, "y"_a, "A line from the current point to (x, y).",
            py::return_value_policy::reference_internal)
        .def(
            "quad_to",
            [](Path& p, double cx, double cy, double x, double y) -> Path& {
                p.quad_to({finite(cx, "cx"), finite(cy, "cy")}, {finite(x, "x"), finite(y, "y")});
                return p;
            },
            "cx"_a, "cy"_a, "x"_a, "y"_a,
            "A quadratic Bezier with control point (cx, cy) to (x, y).",
            py::return_value_policy::reference_internal)
        .def(
            "cubic_to",
            [](Path& p, double c1x, double c1y, double c2x, double c2y, double x,
               double y) -> Path& {
                p.cubic_to({finite(c1x, "c1x"), finite(c1y, "c1y")},
                           {finite(c2x, "c2x"), finite(c2y, "c2y")},
                           {finite(x, "x"), finite(y, "y")});
                return p;
            },
            "c1x"_a, "c1y"_a, "c2x"_a, "c2y"_a, "x"_a, "y"_a,
            "A cubic Bezier with control points (c1x, c1y), (c2x, c2y) to (x, y).",
            py::return_value_policy::reference_internal)
        .def(
            "conic_to",
            [](Path& p, double cx, double cy, double x, double y, double w) -> Path& {
                if (!(w > 0) || !std::isfinite(w)) value_error("w: a conic's weight must be > 0");
                p.conic_to({finite(cx, "cx"), finite(cy, "cy")}, {finite(x, "x"), finite(y, "y")},
                           w);
                return p;
            },
            "cx"_a, "cy"_a, "x"_a, "y"_a, "w"_a,
            "A conic (rational quadratic) with control point (cx, cy) and weight w > 0 to (x, y): "
            "w < 1 an ellipse arc, 1 a parabola, > 1 a hyperbola.",
            py::return_value_policy::reference_internal)
        .def(
            "arc_to",
            [](Path& p, double rx, double ry, double rotation, bool large_arc, bool sweep, double x,
               double y) -> Path& {
                p.arc_to({finite(rx, "rx"), finite(ry, "ry")}, finite(rotation, "rotation"),
                         large_arc, sweep, {finite(x, "x"), finite(y, "y")});
                return p;
            },
            "rx"_a, "ry"_a, "rotation"_a, "large_arc"_a, "sweep"_a, "x"_a, "y"_a,
            "An SVG elliptical arc (radii, x-axis rotation in degrees, flags) to (x, y), as "
            "exact conics.",
            py::return_value_policy::reference_internal)
        .def(
            "close",
            [](Path& p) -> Path& {
                p.close();
                return p;
            },
            "Closes the subpath (with a line back to its start when it ends elsewhere).",
            py::return_value_policy::reference_internal)
        .def_property_readonly(
            "current_point", [](const Path& p) { return xy(p.current_point()); },
            "Where the next segment starts, (x, y).")
        .def_property_readonly(
            "subpath_count", [](const Path& p) { return p.subpaths().size(); },
            "Number of subpaths.")
        .def_property_readonly(
            "segments",
            [](const Path& p) {
                py::list out;
                for (const Subpath& sp : p.subpaths())
                    for (const Segment& s : sp.segments) {
                        py::list pts;
                        for (const Point& q : control_points(s)) pts.append(xy(q));
                        const Conic* k = std::get_if<Conic>(&s);
                        out.append(py::make_tuple(kind_name(s), py::tuple(pts), k ? k->w : 1.0));
                    }
                return out;
            },
            "Every segment as (kind, control points, weight): kind 'line', 'quad', 'cubic' or "
            "'conic', the control points as (x, y) tuples from the start point on, the weight "
            "(1.0 except for conics).")
        .def(
            "bounds", [](const Path& p) { return rect_tuple(p.bounds()); },
            "Tight bounds (x0, y0, x1, y1) over the curves' extrema, or None for an empty path.")
        .def(
            "control_bounds", [](const Path& p) { return rect_tuple(p.control_bounds()); },
            "Bounds of the control points (x0, y0, x1, y1), which hold the path; None if empty.")
        .def(
            "transformed",
            [](const Path& p, const Affine& t) {
                Path q = p;
                q.transform(t);
                return q;
            },
            "transform"_a,
            "A copy mapped by the affine `transform` (exact: control points are mapped).")
        .def(
            "copy", [](const Path& p) { return Path(p); }, "A copy.")
        .def(
            "__copy__", [](const Path& p) { return Path(p); }, "A copy.")
        .def(
            "__deepcopy__", [](const Path& p, py::dict) { return Path(p); }, "memo"_a, "A copy.")
        .def("__len__", &Path::segment_count, "Number of segments over all subpaths.")
        .def("__eq__", &same_path, "Same subpaths, segments and control points, exactly.")
        .def(
            "__ne__", [](const Path& a, const Path& b) { return !same_path(a, b); }, "Inequality.")
        .def(
            "__repr__",
            [](const Path& p) {
                std::ostringstream s;
                s << "<casteljau.Path: " << p.subpaths().size() << " subpath"
                  << (p.subpaths().size() == 1 ? "" : "s") << ", " << p.segment_count()
                  << " segment" << (p.segment_count() == 1 ? "" : "s");
                const Rect b = p.bounds();
                if (!b.is_empty())
                    s << ", bounds (" << b.x0 << ", " << b.y0 << ", " << b.x1 << ", " << b.y1
                      << ")";
                s << ">";
                return s.str();
            },
            "Subpaths, segments and bounds.")
        .def(py::pickle([](const Path& p) { return py::tuple(path_arrays(p)); },
                        [](const py::tuple& s) {
                            if (py::len(s) != 3) value_error("Path state: 3 arrays");
                            return path_from_arrays(s[0], s[1], s[2]);
                        }));
    py::object path_class = m.attr("Path");
    for (const char* verb : {"MOVE", "LINE", "QUAD", "CUBIC", "CONIC", "CLOSE"})
        path_class.attr(verb) = m.attr(verb);
}

} // namespace casteljau::python
