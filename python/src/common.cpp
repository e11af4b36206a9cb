#include "common.h"

#include "casteljau/flatten/uniform.h"
#include "casteljau/render/output_size.h"
#include "casteljau/svg/color.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <thread>

namespace casteljau::python {

namespace {

// The CLI's smallest tolerance (cli/common.h, kMinTolerance).
constexpr double kMinTolerance = 1e-4;

std::string format(const char* fmt, double v) {
    char text[64];
    std::snprintf(text, sizeof text, fmt, v);
    return text;
}

} // namespace

void value_error(const std::string& message) { throw py::value_error(message); }

void os_error(const std::string& message) {
    PyErr_SetString(PyExc_OSError, message.c_str());
    throw py::error_already_set();
}

double finite(double v, const char* what) {
    if (!std::isfinite(v))
        value_error(std::string(what) + ": " + format("%g", v) + " is not finite");
    return v;
}

py::object rect_tuple(const Rect& r) {
    if (r.is_empty()) return py::none();
    return py::make_tuple(r.x0, r.y0, r.x1, r.y1);
}

FillRule to_rule(const std::string& s) {
    if (s == "nonzero") return FillRule::NonZero;
    if (s == "evenodd") return FillRule::EvenOdd;
    value_error("rule '" + s + "': expected 'nonzero' or 'evenodd'");
}

Point to_point(py::handle h, const char* what) {
    if (!PySequence_Check(h.ptr()) || py::isinstance<py::str>(h) || py::isinstance<py::bytes>(h))
        throw py::type_error(std::string(what) + ": expected a point (x, y)");
    const py::sequence s = py::reinterpret_borrow<py::sequence>(h);
    if (py::len(s) != 2) value_error(std::string(what) + ": a point has 2 coordinates");
    return {finite(s[0].cast<double>(), what), finite(s[1].cast<double>(), what)};
}

double checked_tolerance(double tolerance) {
    if (tolerance >= kMinTolerance && tolerance <= 1.0) return tolerance;
    value_error(format("tolerance %g", tolerance) +
                format(": must be a number of device pixels in [%g, 1]", kMinTolerance));
}

FlattenMethod parse_method(const std::string& name) {
    std::string n = name;
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
    if (n == "integral") return FlattenMethod::Integral;
    if (n == "guided") return FlattenMethod::Guided;
    if (n == "adaptive") return FlattenMethod::Adaptive;
    if (n == "uniform") return FlattenMethod::Uniform;
    if (n == "halving") return FlattenMethod::Halving;
    value_error("method '" + name +
                "': expected 'integral', 'guided', 'adaptive', 'uniform' or 'halving'");
}

FlattenOptions flatten_options(double tolerance, const std::string& method,
                               std::optional<int> segments) {
    FlattenOptions o;
    o.tolerance = checked_tolerance(tolerance);
    o.method = parse_method(method);
    if (segments) {
        if (o.method != FlattenMethod::Uniform) value_error("segments: only with method='uniform'");
        if (*segments < 1 || *segments > kMaxUniformSegments)
            value_error("segments " + std::to_string(*segments) + ": must be in [1, " +
                        std::to_string(kMaxUniformSegments) + "]");
        o.segments = *segments;
    }
    return o;
}

Rgba to_rgba(py::handle h, const char* what) {
    if (!PySequence_Check(h.ptr()) || py::isinstance<py::str>(h) || py::isinstance<py::bytes>(h))
        throw py::type_error(std::string(what) + ": expected (r, g, b) or (r, g, b, a)");
    const py::sequence s = py::reinterpret_borrow<py::sequence>(h);
    const std::size_t n = py::len(s);
    if (n != 3 && n != 4) value_error(std::string(what) + ": a color is (r, g, b) or (r, g, b, a)");
    float c[4] = {0, 0, 0, 1};
    for (std::size_t i = 0; i < n; ++i) {
        const double v = s[i].cast<double>();
        if (!(v >= 0 && v <= 1))
            value_error(std::string(what) + ": color components are in [0, 1], not " +
                        format("%g", v));
        c[i] = float(v);
    }
    return {c[0], c[1], c[2], c[3]};
}

Premul to_background(py::handle h) {
    if (h.is_none()) return {};
    if (py::isinstance<py::str>(h)) {
        const std::string text = h.cast<std::string>();
        const std::optional<Rgba> c = parse_color(text);
        if (!c) value_error("background '" + text + "' is not a color");
        return premultiply(*c);
    }
    return premultiply(to_rgba(h, "background"));
}

int resolve_threads(int threads) {
    if (threads < 0 || threads > 1024)
        value_error("threads " + std::to_string(threads) +
                    ": must be in [0, 1024] (0: every core)");
    return threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

void check_canvas_size(int width, int height) {
    if (width < 1 || height < 1 || width > kMaxOutputSide || height > kMaxOutputSide ||
        double(width) * double(height) > kMaxOutputPixels)
        value_error("canvas size " + std::to_string(width) + " x " + std::to_string(height) +
                    " px is outside the limits (1 to " + std::to_string(kMaxOutputSide) +
                    " px a side, at most " + format("%.0f", kMaxOutputPixels) + " pixels)");
}

} // namespace casteljau::python
