// render_svg and render_file: an SVG document to pixels, exactly as the CLI's
// `casteljau render` draws it.
//
// Same pixels by construction: the same reader (svg/reader.h), the same
// output size and limits (render/output_size.h), the same renderer call
// (BandRenderer onto a Canvas, or a Canvas8 for pixels='u8', reset to the
// output size, the view Affine::scale(s)), and, for the array, the same
// straight-RGBA conversion the PNG writer uses (paint/straight_rgba.h). The
// GIL is released around reading, rendering, converting and writing.
#include "casteljau/io/canvas_write.h"
#include "casteljau/io/image_write.h"
#include "casteljau/paint/straight_rgba.h"
#include "casteljau/render/bands.h"
#include "casteljau/render/output_size.h"
#include "casteljau/svg/reader.h"
#include "common.h"

#include <chrono>
#include <cmath>
#include <variant>

namespace casteljau::python {

namespace {

using namespace pybind11::literals;
using Clock = std::chrono::steady_clock;

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

// The options both functions take, checked with the GIL held.
struct Request {
    SizeRequest size;
    Premul background;
    RenderOptions options;
    SvgOptions svg;
    int threads = 1;
    bool canvas_u8 = false;
};

Request make_request(std::optional<double> width, std::optional<double> height,
                     std::optional<double> scale, py::handle background, double tolerance,
                     int threads, const std::string& canvas, bool strict, const std::string& method,
                     std::optional<int> segments, bool antialias,
                     const std::string& gradient_interpolation, const std::string& color_scheme) {
    Request r;
    if (int(width.has_value()) + int(height.has_value()) + int(scale.has_value()) > 1)
        value_error("give at most one of width, height and scale");
    if (width && !(*width >= 1 && *width <= kMaxOutputSide))
        value_error("width " + py::str(py::float_(*width)).cast<std::string>() +
                    ": must be in [1, " + std::to_string(kMaxOutputSide) + "]");
    if (height && !(*height >= 1 && *height <= kMaxOutputSide))
        value_error("height " + py::str(py::float_(*height)).cast<std::string>() +
                    ": must be in [1, " + std::to_string(kMaxOutputSide) + "]");
    if (scale && !(*scale >= 1e-6 && *scale <= 1e6))
        value_error("scale " + py::str(py::float_(*scale)).cast<std::string>() +
                    ": must be in [1e-06, 1e+06]");
    r.size = {width.value_or(0), height.value_or(0), scale.value_or(0)};
    r.svg.media_size = r.size; // what @media width and height are answered for
    r.background = to_background(background);
    r.options.flatten = flatten_options(tolerance, method, segments);
    r.options.antialias = antialias;
    if (gradient_interpolation != "srgb" && gradient_interpolation != "linear")
        value_error("gradient_interpolation '" + gradient_interpolation +
                    "': expected 'srgb' or 'linear'");
    r.options.linear_light_gradients = gradient_interpolation == "linear";
    r.threads = resolve_threads(threads);
    if (canvas != "float" && canvas != "u8")
        value_error("canvas pixels '" + canvas + "': expected 'float' or 'u8'");
    r.canvas_u8 = canvas == "u8";
    r.svg.strict = strict;
    if (color_scheme != "light" && color_scheme != "dark")
        value_error("color_scheme '" + color_scheme + "': expected 'light' or 'dark'");
    r.svg.dark = color_scheme == "dark";
    return r;
}

// Reads the document (GIL released), raising the CLI's located error.
Scene load(const Request& r, const std::string* path, const std::string* text,
           const std::string& name, std::vector<std::string>& warnings) {
    SvgResult doc;
    {
        py::gil_scoped_release release;
        doc = path ? read_svg_file(*path, r.svg) : parse_svg(*text, name, r.svg);
    }
    if (!doc.scene) {
        if (doc.io_error) os_error(doc.error);
        value_error(doc.error);
    }
    for (const SvgDiagnostic& w : doc.warnings) warnings.push_back(w.text());
    return std::move(*doc.scene);
}

OutputSize size_of(const Scene& scene, const Request& r, const std::string& name) {
    OutputSize size = output_size(scene.width, scene.height, r.size);
    if (!size.error.empty()) value_error(name + ": " + size.error);
    return size;
}

// The canvas of the CLI's render_file: sized to the output (not cleared: the
// band renderer clears it to the background), then the same view.
template <class Target>
void draw(const Scene& scene, const OutputSize& size, const Request& r, Target& canvas) {
    canvas.resize(size.width, size.height);
    BandRenderer renderer;
    renderer.render(scene, Affine::scale(size.scale), canvas, r.options, r.background, r.threads);
}

// Calls f with a fresh canvas of the pixel format the request asks for.
template <class F>
void with_canvas(const Request& r, const F& f) {
    if (r.canvas_u8) {
        Canvas8 c;
        f(c);
    } else {
        Canvas c;
        f(c);
    }
}

py::tuple render_svg(std::optional<std::string> path, std::optional<std::string> text,
                     const std::string& name, std::optional<double> width,
                     std::optional<double> height, std::optional<double> scale,
                     py::object background, double tolerance, int threads,
                     const std::string& pixels, const std::string& canvas, bool strict,
                     const std::string& method, std::optional<int> segments, bool antialias,
                     const std::string& gradient_interpolation, const std::string& color_scheme) {
    // Auto: the canvas of the array's type, as the CLI's for a file's.
    const std::string drawn_on = canvas != "auto" ? canvas : pixels == "float32" ? "float" : "u8";
    const Request r =
        make_request(width, height, scale, background, tolerance, threads, drawn_on, strict, method,
                     segments, antialias, gradient_interpolation, color_scheme);
    if (pixels != "u8" && pixels != "float32")
        value_error("pixels '" + pixels + "': expected 'u8' or 'float32'");
    if (!path && !text) throw py::type_error("render_svg: no source");
    std::vector<std::string> warnings;
    const Scene scene = load(r, path ? &*path : nullptr, text ? &*text : nullptr, name, warnings);
    const OutputSize size = size_of(scene, r, path ? *path : name);
    const std::vector<py::ssize_t> shape{size.height, size.width, 4};
    const bool bytes = pixels == "u8";
    py::array out =
        bytes ? py::array(py::array_t<std::uint8_t>(shape)) : py::array(py::array_t<float>(shape));
    void* data = out.mutable_data();
    const std::size_t n = std::size_t(out.size());
    {
        py::gil_scoped_release release;
        const auto finish = [&](auto& c) {
            draw(scene, size, r, c);
            if (bytes)
                straight_rgba8(c, std::span<std::uint8_t>(static_cast<std::uint8_t*>(data), n));
            else
                straight_rgba(c, std::span<float>(static_cast<float*>(data), n));
        };
        with_canvas(r, finish);
    }
    return py::make_tuple(out, warnings);
}

py::dict render_file(const std::string& input, const std::string& output,
                     std::optional<double> width, std::optional<double> height,
                     std::optional<double> scale, py::object background, double tolerance,
                     int threads, const std::string& pixels, bool strict, const std::string& method,
                     std::optional<int> segments, bool antialias,
                     const std::string& gradient_interpolation, const std::string& color_scheme) {
    const auto t0 = Clock::now();
    // Auto: the CLI's --pixels auto, 8-bit for 8-bit files, float for EXR and TIFF.
    const std::string drawn_on = pixels != "auto" ? pixels : stores_float(output) ? "float" : "u8";
    const Request r =
        make_request(width, height, scale, background, tolerance, threads, drawn_on, strict, method,
                     segments, antialias, gradient_interpolation, color_scheme);
    std::vector<std::string> warnings;
    const Scene scene = load(r, &input, nullptr, input, warnings);
    const double parse_ms = ms(Clock::now() - t0);
    const OutputSize size = size_of(scene, r, input);
    double frame_ms = 0, encode_ms = 0;
    std::string error;
    {
        py::gil_scoped_release release;
        const auto finish = [&](auto& c) {
            const auto f0 = Clock::now();
            draw(scene, size, r, c);
            frame_ms = ms(Clock::now() - f0);
            const auto e0 = Clock::now();
            error = write_canvas_atomic(output, c);
            encode_ms = ms(Clock::now() - e0);
        };
        with_canvas(r, finish);
    }
    if (!error.empty()) os_error(error);
    py::dict stats;
    stats["input"] = input;
    stats["output"] = output;
    stats["width"] = size.width;
    stats["height"] = size.height;
    stats["threads"] = r.threads;
    stats["pixels"] = r.canvas_u8 ? "u8" : "float";
    stats["parse_ms"] = parse_ms;
    stats["frame_ms"] = frame_ms;
    stats["encode_ms"] = encode_ms;
    stats["total_ms"] = ms(Clock::now() - t0);
    stats["warnings"] = warnings;
    return stats;
}

} // namespace

void bind_render(py::module_& m) {
    m.def("_render_svg", &render_svg, "path"_a, "text"_a, "name"_a, py::kw_only(),
          "width"_a = py::none(), "height"_a = py::none(), "scale"_a = py::none(),
          "background"_a = py::none(), "tolerance"_a = 0.25, "threads"_a = 0, "pixels"_a = "u8",
          "canvas"_a = "auto", "strict"_a = false, "method"_a = "guided", "segments"_a = py::none(),
          "antialias"_a = true, "gradient_interpolation"_a = "srgb", "color_scheme"_a = "light",
          "Renders an SVG file (path) or text (with `name` for messages); returns (array, "
          "warnings). See casteljau.render_svg.");
    m.def("_render_file", &render_file, "input"_a, "output"_a, py::kw_only(),
          "width"_a = py::none(), "height"_a = py::none(), "scale"_a = py::none(),
          "background"_a = py::none(), "tolerance"_a = 0.25, "threads"_a = 1, "pixels"_a = "auto",
          "strict"_a = false, "method"_a = "guided", "segments"_a = py::none(),
          "antialias"_a = true, "gradient_interpolation"_a = "srgb", "color_scheme"_a = "light",
          "Renders an SVG file to an image file; returns the stats. See casteljau.render_file.");
}

} // namespace casteljau::python
