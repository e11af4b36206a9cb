// What the binding files share: the pybind11 includes, argument checks that
// raise ValueError with the CLI's wording, and conversions between library
// values and Python ones (points as (x, y) tuples, colors, options by name).
#pragma once

#include "casteljau/flatten/flatten.h"
#include "casteljau/geom/affine.h"
#include "casteljau/geom/rect.h"
#include "casteljau/paint/color.h"
#include "casteljau/raster/sweep.h"

#include <optional>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <string>

namespace casteljau::python {

namespace py = pybind11;

/// The submodules' registration, in the order module.cpp calls them.
void bind_geometry(py::module_& m);
void bind_hit(py::module_& m); // after bind_geometry: adds to Path
void bind_paint(py::module_& m);
void bind_drawing(py::module_& m);
void bind_render(py::module_& m);
void bind_flatten(py::module_& m);
void bind_patch(py::module_& m);

/// Raises ValueError(message).
[[noreturn]] void value_error(const std::string& message);

/// Raises OSError(message).
[[noreturn]] void os_error(const std::string& message);

/// A finite coordinate, or ValueError naming `what`.
double finite(double v, const char* what);

/// (x0, y0, x1, y1), or None for an empty rectangle.
py::object rect_tuple(const Rect& r);

/// "nonzero" or "evenodd"; ValueError otherwise.
FillRule to_rule(const std::string& s);

/// A point from any sequence of two numbers ((x, y), a list, a 1-D array).
Point to_point(py::handle h, const char* what);

/// The flattening tolerance, checked as the CLI checks --tolerance ([1e-4, 1] px).
double checked_tolerance(double tolerance);

/// "integral", "guided", "adaptive", "uniform" or "halving" (any case); ValueError otherwise.
FlattenMethod parse_method(const std::string& name);

/// FlattenOptions from the Python keywords; `segments` only with "uniform".
FlattenOptions flatten_options(double tolerance, const std::string& method,
                               std::optional<int> segments);

/// A straight color from (r, g, b) or (r, g, b, a), components in [0, 1].
Rgba to_rgba(py::handle h, const char* what);

/// A background: None (transparent), a CSS color string, or an (r, g, b[, a]) tuple.
Premul to_background(py::handle h);

/// The number of threads for `threads` (0: every core); ValueError outside [0, 1024].
int resolve_threads(int threads);

/// Whether a canvas of width x height is within the output limits; ValueError if not.
void check_canvas_size(int width, int height);

} // namespace casteljau::python
