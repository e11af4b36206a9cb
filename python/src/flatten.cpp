// flatten: a Path (or SVG path data) to polylines, with the measured error,
// as `casteljau flatten --json` reports them (cli/flatten_command.cpp): the
// same flatten_path call with the exact error measure, the same points.
#include "casteljau/curve/path_data.h"
#include "casteljau/flatten/path_flatten.h"
#include "common.h"

#include <cmath>

namespace casteljau::python {

namespace {

using namespace pybind11::literals;

const char* method_name(FlattenMethod m) {
    switch (m) {
    case FlattenMethod::Integral:
        return "integral";
    case FlattenMethod::Guided:
        return "guided";
    case FlattenMethod::Adaptive:
        return "adaptive";
    case FlattenMethod::Uniform:
        return "uniform";
    case FlattenMethod::Halving:
        return "halving";
    default:
        return "uniform_best";
    }
}

py::tuple flatten(py::handle path_or_d, double tolerance, const std::string& method,
                  std::optional<int> segments, std::optional<Affine> transform) {
    const FlattenOptions options = flatten_options(tolerance, method, segments);
    const Affine to_device = transform.value_or(Affine::identity());
    if (!to_device.is_finite()) value_error("transform: must be finite");
    Path path;
    if (py::isinstance<py::str>(path_or_d) || py::isinstance<py::bytes>(path_or_d)) {
        const std::string d = path_or_d.cast<std::string>();
        PathDataResult parsed;
        {
            py::gil_scoped_release release;
            parsed = parse_path_data(d);
        }
        if (parsed.error)
            value_error("path data: at offset " + std::to_string(parsed.error->offset) + ": " +
                        parsed.error->message);
        path = std::move(parsed.path);
    } else if (py::isinstance<Path>(path_or_d)) {
        path = path_or_d.cast<const Path&>();
    } else {
        throw py::type_error("flatten: expected a Path or a string of SVG path data");
    }
    std::vector<Polyline> lines;
    FlattenStats stats;
    {
        py::gil_scoped_release release;
        stats = flatten_path(path, to_device, options, lines, true);
    }
    std::size_t n = 0;
    for (const Polyline& l : lines) n += l.points.size();
    py::array_t<double> points({py::ssize_t(n), py::ssize_t(2)});
    double* out = points.mutable_data();
    py::list subpaths;
    std::size_t first = 0;
    for (const Polyline& l : lines) {
        for (const Point& p : l.points) *out++ = p.x, *out++ = p.y;
        py::dict s;
        s["first"] = first;
        s["count"] = l.points.size();
        s["closed"] = l.closed;
        subpaths.append(s);
        first += l.points.size();
    }
    py::dict info;
    info["segments"] = stats.segments_out;
    info["max_error_px"] = stats.max_error;
    info["curves_in"] = stats.curves_in;
    info["max_depth"] = stats.max_depth;
    info["subpaths"] = subpaths;
    info["tolerance"] = options.tolerance;
    info["method"] = method_name(options.method);
    return py::make_tuple(points, info);
}

} // namespace

void bind_flatten(py::module_& m) {
    m.def("flatten", &flatten, "path_or_d"_a, "tolerance"_a = 0.25, "method"_a = "guided",
          "segments"_a = py::none(), py::kw_only(), "transform"_a = py::none(),
          R"doc(
Flattens a Path, or a string of SVG path data, into polylines within
`tolerance` device pixels (in [1e-4, 1]) of the curves.

method: 'guided' (default, fastest), 'integral' (near the fewest segments),
'adaptive' (greedy), 'uniform' (`segments` per curve, or without it the fewest
Wang's bound allows) or 'halving' (textbook midpoint subdivision). `transform` maps the path to
device space first (default: path units are pixels).

Returns (points, info): points is an (N, 2) float64 array of every
polyline's vertices, one subpath after another (a closed one ends on its
first point); info is a dict with 'segments' (polyline edges),
'max_error_px' (the largest distance between curve and polyline, measured
exactly as `casteljau flatten --json` does), 'curves_in', 'max_depth',
'subpaths' (a list of {'first', 'count', 'closed'} into points),
'tolerance' and 'method'. Bad path data raises ValueError('path data: at
offset N: what'). The GIL is released while flattening.)doc");
}

} // namespace casteljau::python
