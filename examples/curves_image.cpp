// Renders the bundled curve examples to an image: every curve kind the
// library has, each flattened adaptively (blue, upper copy) and by uniform
// sampling with the fewest segments that measure within the same tolerance
// (orange, lower copy), with their vertices as dots. Where the curvature
// varies, the adaptive vertices crowd into the bends and the uniform ones
// do not. Prints one line per curve with both segment counts.
//
// Usage: curves_image OUT.png [TOLERANCE_PX]
//
// The drawing is deliberately simple (distance-based antialiased strokes into
// a float buffer); the real rasterizer is the raster/ stage's job.
#include "casteljau/curve/arc.h"
#include "casteljau/curve/bspline.h"
#include "casteljau/flatten/error.h"
#include "casteljau/flatten/flatten.h"
#include "casteljau/io/image_write.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

using namespace casteljau;

namespace {

struct Color {
    float r, g, b;
};

class Canvas {
  public:
    Canvas(int w, int h) : w_(w), h_(h), px_(std::size_t(w) * std::size_t(h) * 4, 1.0f) {}
    // Antialiased disc or capsule: coverage = clamp(r + 1/2 - distance).
    void capsule(Point a, Point b, double radius, Color c) {
        const Rect box = Rect::from_points(a, b).inflated(radius + 1);
        const int x0 = std::max(0, int(box.x0)), x1 = std::min(w_ - 1, int(box.x1));
        const int y0 = std::max(0, int(box.y0)), y1 = std::min(h_ - 1, int(box.y1));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double d = distance_to_segment({x + 0.5, y + 0.5}, a, b);
                const float cov = float(std::clamp(radius + 0.5 - d, 0.0, 1.0));
                float* p = &px_[(std::size_t(y) * std::size_t(w_) + std::size_t(x)) * 4];
                p[0] += (c.r - p[0]) * cov, p[1] += (c.g - p[1]) * cov, p[2] += (c.b - p[2]) * cov;
            }
    }
    ImageView view() const { return {w_, h_, px_}; }

  private:
    int w_, h_;
    std::vector<float> px_;
};

struct Example {
    const char* name;
    // Flattens with the given method (Uniform: `n` segments) into vertices
    // after `start`; returns the measured maximum error.
    std::function<double(const FlattenOptions&, Point& start, std::vector<FlatVertex>&)> flatten;
    std::function<int(double tol)> best_uniform;
};

template <class Curve>
Example example(const char* name, Curve c) {
    return {name,
            [c](const FlattenOptions& o, Point& start, std::vector<FlatVertex>& v) {
                start = c.start();
                flatten_curve(c, o, [&](const FlatVertex& x) { v.push_back(x); });
                return polyline_error(c, c.start(), v);
            },
            [c](double tol) { return best_uniform_segments(c, tol, wang_segments(c, tol)); }};
}

void draw(Canvas& canvas, Point start, const std::vector<FlatVertex>& v, Vec2 offset, Color c) {
    Point a = start + offset;
    canvas.capsule(a, a, 2.6, c);
    for (const FlatVertex& x : v) {
        const Point b = x.p + offset;
        canvas.capsule(a, b, 0.9, c);
        canvas.capsule(b, b, 2.6, c);
        a = b;
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s OUT.png [TOLERANCE_PX]\n", argv[0]);
        return 2;
    }
    const double tol = argc > 2 ? std::atof(argv[2]) : 0.25;
    if (!(tol > 0 && tol <= 1)) {
        std::fprintf(stderr, "%s: tolerance must be in (0, 1]\n", argv[0]);
        return 2;
    }
    std::array<Conic, 4> arc;
    svg_arc_to_conics({{20, 150}, {230, 60}, {120, 60}, 20, true, false}, arc);
    BSpline spline{3, {{10, 150}, {40, 10}, {90, 160}, {140, 20}, {190, 150}, {240, 40}}, {}};
    spline.knots = clamped_uniform_knots(3, spline.points.size());
    const auto spline_pieces = spline.to_beziers();
    Bezier high;
    high.degree = 6;
    const Point hp[] = {{10, 150},  {30, -60},  {90, 250}, {130, -80},
                        {170, 250}, {220, -40}, {240, 150}};
    std::copy(std::begin(hp), std::end(hp), high.p.begin());
    const std::vector<Example> examples = {
        example("cubic S-curve", CubicBez{{10, 150}, {110, -80}, {140, 260}, {240, 30}}),
        example("cubic loop", CubicBez{{10, 150}, {300, 0}, {-50, 0}, {240, 150}}),
        example("near-cusp cubic", CubicBez{{10, 150}, {240, 10}, {10, 12}, {240, 150}}),
        example("quadratic", QuadBez{{10, 150}, {60, -60}, {240, 150}}),
        example("conic (w=3)", Conic{{10, 150}, {125, 10}, {240, 150}, 3.0}),
        example("SVG arc, first conic", arc[0]),
        example("degree-6 Bezier", high),
        example("B-spline piece", spline_pieces[1]),
        example("NURBS circle quarter", Nurbs::circle({125, 90}, 70).to_beziers()[1]),
    };

    const int cols = 3, cell_w = 260, cell_h = 360;
    const int rows = int(examples.size() + cols - 1) / cols;
    Canvas canvas(cols * cell_w, rows * cell_h);
    std::printf("tolerance %.3g px\n%-22s %9s %9s\n", tol, "curve", "adaptive", "uniform");
    for (std::size_t i = 0; i < examples.size(); ++i) {
        const Vec2 cell{double(int(i) % cols * cell_w), double(int(i) / cols * cell_h)};
        const Example& e = examples[i];
        Point start;
        std::vector<FlatVertex> adaptive, uniform;
        const double ea = e.flatten({tol, FlattenMethod::Adaptive, 0}, start, adaptive);
        const int n = e.best_uniform(tol);
        const double eu = e.flatten({tol, FlattenMethod::Uniform, n}, start, uniform);
        draw(canvas, start, adaptive, cell + Vec2{0, 10}, {0.12f, 0.35f, 0.85f});
        draw(canvas, start, uniform, cell + Vec2{0, 180}, {0.95f, 0.5f, 0.1f});
        std::printf("%-22s %9zu %9zu   (errors %.3f / %.3f px)\n", e.name, adaptive.size(),
                    uniform.size(), ea, eu);
    }
    const std::string err = write_image_atomic(argv[1], canvas.view());
    if (!err.empty()) {
        std::fprintf(stderr, "%s\n", err.c_str());
        return 1;
    }
    std::printf("wrote %s\n", argv[1]);
    return 0;
}
