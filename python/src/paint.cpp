// Paint, StrokeGeometry, Canvas and Canvas8.
//
// A Canvas is the library's float canvas (premultiplied RGBA, 16 bytes a
// pixel, rows of exactly width pixels with no padding), exposed through the
// buffer protocol: numpy.asarray(canvas) is an (H, W, 4) float32 view of
// the canvas's own memory (strides W*16, 16, 4), writable, kept alive by
// the array. Canvas8 is the same at 8 bits a channel (uint8, strides W*4,
// 4, 1). A canvas never changes size, so a view stays valid as long as it
// lives. to_rgba8() / to_rgba() convert to straight RGBA with the library's
// conversion (paint/straight_rgba.h), the one the PNG writer uses.
#include "casteljau/io/canvas_write.h"
#include "casteljau/paint/straight_rgba.h"
#include "casteljau/render/drawing.h"
#include "casteljau/svg/color.h"
#include "common.h"

#include <cmath>
#include <sstream>

namespace casteljau::python {

namespace {

using namespace pybind11::literals;

std::vector<GradientStop> to_stops(const py::sequence& stops) {
    std::vector<GradientStop> out;
    for (const py::handle item : stops) {
        if (!PySequence_Check(item.ptr()) || py::len(item) != 2)
            value_error("stops: each stop is (offset, (r, g, b[, a]))");
        const py::sequence s = py::reinterpret_borrow<py::sequence>(item);
        const double offset = s[0].cast<double>();
        if (!(offset >= 0 && offset <= 1)) value_error("stops: offsets are in [0, 1]");
        if (!out.empty() && offset < out.back().offset)
            value_error("stops: offsets must not decrease");
        out.push_back({float(offset), to_rgba(s[1], "stops")});
    }
    if (out.empty()) value_error("stops: a gradient needs at least one stop");
    return out;
}

Spread to_spread(const std::string& s) {
    if (s == "pad") return Spread::Pad;
    if (s == "reflect") return Spread::Reflect;
    if (s == "repeat") return Spread::Repeat;
    value_error("spread '" + s + "': expected 'pad', 'reflect' or 'repeat'");
}

LineJoin to_join(const std::string& s) {
    if (s == "miter") return LineJoin::Miter;
    if (s == "round") return LineJoin::Round;
    if (s == "bevel") return LineJoin::Bevel;
    value_error("join '" + s + "': expected 'miter', 'round' or 'bevel'");
}

LineCap to_cap(const std::string& s) {
    if (s == "butt") return LineCap::Butt;
    if (s == "round") return LineCap::Round;
    if (s == "square") return LineCap::Square;
    value_error("cap '" + s + "': expected 'butt', 'round' or 'square'");
}

const char* join_name(LineJoin j) {
    return j == LineJoin::Miter ? "miter" : j == LineJoin::Round ? "round" : "bevel";
}
const char* cap_name(LineCap c) {
    return c == LineCap::Butt ? "butt" : c == LineCap::Round ? "round" : "square";
}

double non_negative(double v, const char* what) {
    if (!(v >= 0) || !std::isfinite(v)) value_error(std::string(what) + " must be finite and >= 0");
    return v;
}

std::vector<double> to_dashes(const std::vector<double>& d) {
    for (double v : d) non_negative(v, "dashes");
    return d;
}

float to_opacity(double v) {
    if (!(v >= 0 && v <= 1)) value_error("opacity must be in [0, 1]");
    return float(v);
}

template <class Pixel>
py::array straight(const BasicCanvas<Pixel>& c, bool bytes) {
    const py::ssize_t h = c.height(), w = c.width();
    if (bytes) {
        py::array_t<std::uint8_t> out({h, w, py::ssize_t(4)});
        const std::span<std::uint8_t> dst(out.mutable_data(), std::size_t(out.size()));
        py::gil_scoped_release release;
        straight_rgba8(c, dst);
        return out;
    }
    py::array_t<float> out({h, w, py::ssize_t(4)});
    const std::span<float> dst(out.mutable_data(), std::size_t(out.size()));
    py::gil_scoped_release release;
    straight_rgba(c, dst);
    return out;
}

template <class Pixel>
void save(const BasicCanvas<Pixel>& c, const std::string& path) {
    std::string error;
    {
        py::gil_scoped_release release;
        error = write_canvas_atomic(path, c);
    }
    if (!error.empty()) os_error(error);
}

template <class Pixel, class Scalar>
void bind_canvas(py::module_& m, const char* name, const char* doc) {
    using C = BasicCanvas<Pixel>;
    py::class_<C>(m, name, py::buffer_protocol(), doc)
        .def(py::init([](int width, int height, py::object background) {
                 check_canvas_size(width, height);
                 const Premul bg = to_background(background);
                 auto c = std::make_unique<C>();
                 c->reset(width, height, 0, 0, bg);
                 return c;
             }),
             "width"_a, "height"_a, "background"_a = py::none(),
             "A width x height canvas cleared to `background` (None: transparent; a CSS color "
             "string or an (r, g, b[, a]) tuple). Limits: 16384 px a side, 2^26 pixels.")
        .def_buffer([](C& c) {
            constexpr py::ssize_t channel = sizeof(Scalar);
            return py::buffer_info(
                reinterpret_cast<Scalar*>(c.row(0)), channel,
                py::format_descriptor<Scalar>::format(), 3,
                {py::ssize_t(c.height()), py::ssize_t(c.width()), py::ssize_t(4)},
                {py::ssize_t(c.width()) * 4 * channel, 4 * channel, channel}, false);
        })
        .def_property_readonly("width", &C::width, "Width in pixels.")
        .def_property_readonly("height", &C::height, "Height in pixels.")
        .def_property_readonly(
            "shape", [](const C& c) { return py::make_tuple(c.height(), c.width(), 4); },
            "(height, width, 4), the shape of numpy.asarray(canvas).")
        .def(
            "fill",
            [](C& c, py::object background) {
                const Premul bg = to_background(background);
                c.fill(bg);
            },
            "color"_a = py::none(),
            "Sets every pixel to `color` (None: transparent; a CSS color or an (r, g, b[, a]) "
            "tuple).")
        .def(
            "to_rgba8", [](const C& c) { return straight(c, true); },
            "The pixels as straight (un-premultiplied) RGBA, an (H, W, 4) uint8 array: exactly "
            "the values a PNG of this canvas holds.")
        .def(
            "to_rgba", [](const C& c) { return straight(c, false); },
            "The pixels as straight RGBA, an (H, W, 4) float32 array in [0, 1].")
        .def("save", &save<Pixel>, "path"_a,
             "Writes the canvas as an image (format from the extension: png, tif, exr, jpg), "
             "atomically; OSError on failure.")
        .def("__repr__", [name](const C& c) {
            return std::string("<casteljau.") + name + " " + std::to_string(c.width()) + " x " +
                   std::to_string(c.height()) + ">";
        });
}

} // namespace

void bind_paint(py::module_& m) {
    py::class_<Paint>(m, "Paint", R"doc(
What a fill or a stroke is painted with: a solid color or a gradient, and an
opacity. Colors are straight sRGB components in [0, 1]. Build one with
Paint.solid, Paint.css, Paint.linear or Paint.radial.)doc")
        .def_static(
            "solid",
            [](double r, double g, double b, double a) {
                return Paint::solid(to_rgba(py::make_tuple(r, g, b, a), "color"));
            },
            "r"_a, "g"_a, "b"_a, "a"_a = 1.0, "A solid color (components in [0, 1]).")
        .def_static(
            "css",
            [](const std::string& text) {
                const std::optional<Rgba> c = parse_color(text);
                if (!c) value_error("'" + text + "' is not a color");
                return Paint::solid(*c);
            },
            "color"_a, "A solid color from CSS text: a name, #rgb[a], #rrggbb[aa], rgb(), hsl()...")
        .def_static(
            "linear",
            [](double x0, double y0, double x1, double y1, const py::sequence& stops,
               const std::string& spread) {
                Paint p = Paint::linear({finite(x0, "x0"), finite(y0, "y0")},
                                        {finite(x1, "x1"), finite(y1, "y1")}, to_stops(stops));
                std::const_pointer_cast<Gradient>(p.gradient)->spread = to_spread(spread);
                return p;
            },
            "x0"_a, "y0"_a, "x1"_a, "y1"_a, "stops"_a, py::kw_only(), "spread"_a = "pad",
            "A linear gradient from (x0, y0) to (x1, y1) in the shape's path coordinates. "
            "`stops`: a list of (offset, (r, g, b[, a])), offsets in [0, 1] not decreasing; "
            "`spread`: 'pad', 'reflect' or 'repeat'.")
        .def_static(
            "radial",
            [](double cx, double cy, double r, const py::sequence& stops, std::optional<double> fx,
               std::optional<double> fy, const std::string& spread) {
                auto g = std::make_shared<Gradient>();
                g->kind = Gradient::Kind::Radial;
                g->center = {finite(cx, "cx"), finite(cy, "cy")};
                g->radius = non_negative(r, "r");
                g->focal = {finite(fx.value_or(cx), "fx"), finite(fy.value_or(cy), "fy")};
                g->object_bounding_box = false;
                g->spread = to_spread(spread);
                g->stops = to_stops(stops);
                return Paint{{}, std::move(g), 1};
            },
            "cx"_a, "cy"_a, "r"_a, "stops"_a, py::kw_only(), "fx"_a = py::none(),
            "fy"_a = py::none(), "spread"_a = "pad",
            "A radial gradient: centre (cx, cy), radius r, focal point (fx, fy) (default the "
            "centre), in path coordinates; stops and spread as for linear().")
        .def_property(
            "opacity", [](const Paint& p) { return p.opacity; },
            [](Paint& p, double v) { p.opacity = to_opacity(v); },
            "Multiplies the paint's alpha, in [0, 1].")
        .def_property_readonly(
            "color",
            [](const Paint& p) {
                return py::make_tuple(p.color.r, p.color.g, p.color.b, p.color.a);
            },
            "The solid color (r, g, b, a) (unused by a gradient).")
        .def_property_readonly(
            "kind",
            [](const Paint& p) {
                return !p.gradient                                  ? "solid"
                       : p.gradient->kind == Gradient::Kind::Linear ? "linear"
                                                                    : "radial";
            },
            "'solid', 'linear' or 'radial'.")
        .def("__repr__", [](const Paint& p) {
            std::ostringstream s;
            if (!p.gradient)
                s << "Paint.solid(" << p.color.r << ", " << p.color.g << ", " << p.color.b << ", "
                  << p.color.a << ")";
            else
                s << "<casteljau.Paint "
                  << (p.gradient->kind == Gradient::Kind::Linear ? "linear" : "radial")
                  << " gradient, " << p.gradient->stops.size() << " stops>";
            if (p.opacity != 1) s << " opacity " << p.opacity;
            return s.str();
        });

    py::class_<StrokeGeometry>(m, "StrokeGeometry", R"doc(
The shape of a stroke: width (in path coordinates), join ('miter', 'round',
'bevel'), cap ('butt', 'round', 'square'), miter_limit (>= 1), dashes (a list
of lengths; empty for a solid line) and dash_offset.)doc")
        .def(
            py::init([](double width, const std::string& join, const std::string& cap,
                        double miter_limit, const std::vector<double>& dashes, double dash_offset) {
                StrokeGeometry g;
                g.width = non_negative(width, "width");
                g.join = to_join(join);
                g.cap = to_cap(cap);
                if (!(miter_limit >= 1) || !std::isfinite(miter_limit))
                    value_error("miter_limit must be finite and >= 1");
                g.miter_limit = miter_limit;
                g.dashes = to_dashes(dashes);
                g.dash_offset = finite(dash_offset, "dash_offset");
                return g;
            }),
            py::kw_only(), "width"_a = 1.0, "join"_a = "miter", "cap"_a = "butt",
            "miter_limit"_a = 4.0, "dashes"_a = std::vector<double>{}, "dash_offset"_a = 0.0,
            "A stroke geometry; every option keyword-only, with SVG's initial values.")
        .def_property(
            "width", [](const StrokeGeometry& g) { return g.width; },
            [](StrokeGeometry& g, double v) { g.width = non_negative(v, "width"); },
            "Stroke width, path coordinates.")
        .def_property(
            "join", [](const StrokeGeometry& g) { return join_name(g.join); },
            [](StrokeGeometry& g, const std::string& v) { g.join = to_join(v); },
            "'miter', 'round' or 'bevel'.")
        .def_property(
            "cap", [](const StrokeGeometry& g) { return cap_name(g.cap); },
            [](StrokeGeometry& g, const std::string& v) { g.cap = to_cap(v); },
            "'butt', 'round' or 'square'.")
        .def_property(
            "miter_limit", [](const StrokeGeometry& g) { return g.miter_limit; },
            [](StrokeGeometry& g, double v) {
                if (!(v >= 1) || !std::isfinite(v))
                    value_error("miter_limit must be finite and >= 1");
                g.miter_limit = v;
            },
            "Miter limit (>= 1).")
        .def_property(
            "dashes", [](const StrokeGeometry& g) { return g.dashes; },
            [](StrokeGeometry& g, const std::vector<double>& v) { g.dashes = to_dashes(v); },
            "Dash lengths (a list; empty: solid).")
        .def_property(
            "dash_offset", [](const StrokeGeometry& g) { return g.dash_offset; },
            [](StrokeGeometry& g, double v) { g.dash_offset = finite(v, "dash_offset"); },
            "Where along the dash pattern the stroke starts.")
        .def("__repr__",
             [](const StrokeGeometry& g) {
                 std::ostringstream s;
                 s << "StrokeGeometry(width=" << g.width << ", join='" << join_name(g.join)
                   << "', cap='" << cap_name(g.cap) << "', miter_limit=" << g.miter_limit
                   << ", dashes=[";
                 for (std::size_t i = 0; i < g.dashes.size(); ++i)
                     s << (i ? ", " : "") << g.dashes[i];
                 s << "], dash_offset=" << g.dash_offset << ")";
                 return s.str();
             })
        .def(py::pickle(
            [](const StrokeGeometry& g) {
                return py::make_tuple(g.width, join_name(g.join), cap_name(g.cap), g.miter_limit,
                                      g.dashes, g.dash_offset);
            },
            [](const py::tuple& s) {
                if (py::len(s) != 6) value_error("StrokeGeometry state: 6 values");
                StrokeGeometry g;
                g.width = non_negative(s[0].cast<double>(), "width");
                g.join = to_join(s[1].cast<std::string>());
                g.cap = to_cap(s[2].cast<std::string>());
                g.miter_limit = s[3].cast<double>();
                g.dashes = to_dashes(s[4].cast<std::vector<double>>());
                g.dash_offset = finite(s[5].cast<double>(), "dash_offset");
                return g;
            }));

    bind_canvas<Premul, float>(m, "Canvas", R"doc(
A float RGBA canvas, premultiplied, 16 bytes a pixel: what the renderer
composites onto without rounding (a Drawing renders onto it).

Buffer protocol, zero copy: ``numpy.asarray(canvas)`` is an (H, W, 4)
float32 array sharing the canvas's memory (rows of exactly W pixels, no
padding; strides W*16, 16, 4), writable; the canvas stays alive while the
array does. Values are premultiplied; to_rgba8() and to_rgba() give straight
RGBA as a PNG holds it.)doc");
    bind_canvas<Premul8, std::uint8_t>(m, "Canvas8", R"doc(
An 8-bit RGBA canvas, premultiplied, bytes R, G, B, A: a quarter of the
memory of Canvas; each composite is rounded to the nearest 1/255.

Buffer protocol, zero copy: ``numpy.asarray(canvas8)`` is an (H, W, 4) uint8
array sharing its memory (strides W*4, 4, 1). Values are premultiplied;
to_rgba8() gives straight RGBA.)doc");
}

} // namespace casteljau::python
