#include "bench_scenes.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

namespace casteljau::bench {

namespace {

class Rng {
  public:
    explicit Rng(unsigned seed) : gen_(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(gen_); }
    Point point() { return {uniform(0, kSceneSize), uniform(0, kSceneSize)}; }
    Rgba color(float alpha) {
        return {float(uniform(0, 1)), float(uniform(0, 1)), float(uniform(0, 1)), alpha};
    }

  private:
    std::mt19937_64 gen_;
};

Scene empty_scene() {
    Scene s;
    s.width = s.height = kSceneSize;
    return s;
}

Path rect(Point a, Point b) {
    Path p;
    p.move_to(a);
    p.line_to({b.x, a.y});
    p.line_to(b);
    p.line_to({a.x, b.y});
    p.close();
    return p;
}

void add_painted(Scene& s, Path p, Fill fill) {
    Shape shape;
    shape.path = std::move(p);
    shape.fill = std::move(fill);
    s.root.children.push_back(Node{std::move(shape)});
}

void add_fill(Scene& s, Path p, Rgba color, FillRule rule = FillRule::NonZero) {
    add_painted(s, std::move(p), Fill{color, nullptr, 1, rule});
}

void add_stroke(Scene& s, Path p, Rgba color, double width) {
    Shape shape;
    shape.path = std::move(p);
    Stroke st{color, nullptr, 1, {}};
    st.geometry.width = width;
    shape.stroke = st;
    s.root.children.push_back(Node{std::move(shape)});
}

// A closed loop of four cubics around `c` with radii jittered per point.
Path blob(Rng& rng, Point c, double r) {
    Path p;
    const auto at = [&](double a, double k) {
        return c + Vec2{std::cos(a), std::sin(a)} * (r * k * rng.uniform(0.6, 1.2));
    };
    const double q = std::numbers::pi / 2;
    const double a0 = rng.uniform(0, q);
    p.move_to(at(a0, 1));
    for (int i = 1; i <= 4; ++i) {
        const double a = a0 + i * q;
        const Point end = i == 4 ? p.subpaths().back().start : at(a, 1);
        p.cubic_to(at(a - 2 * q / 3, 1.3), at(a - q / 3, 1.3), end);
    }
    p.close();
    return p;
}

void ellipse(Path& p, Point c, double rx, double ry, bool clockwise) {
    p.move_to(c + Vec2{rx, 0});
    p.arc_to({rx, ry}, 0, false, clockwise, c + Vec2{-rx, 0});
    p.arc_to({rx, ry}, 0, false, clockwise, c + Vec2{rx, 0});
    p.close();
}

// A scene of n shapes, the i-th added by add(rng, scene, i, a random point).
template <class Add>
Scene generate(unsigned seed, int n, Add add) {
    Rng rng(seed);
    Scene s = empty_scene();
    for (int i = 0; i < n; ++i) {
        const Point at = rng.point();
        add(rng, s, i, at);
    }
    return s;
}

} // namespace

Scene random_blobs(unsigned seed, int n) {
    return generate(seed, n, [](Rng& rng, Scene& s, int, Point c) {
        add_fill(s, blob(rng, c, rng.uniform(5, 30)), rng.color(0.8f));
    });
}

Scene large_ellipse() {
    Scene s = empty_scene();
    Path p;
    ellipse(p, {512, 512}, 480, 320, true);
    add_fill(s, std::move(p), {0.1f, 0.4f, 0.8f, 1});
    return s;
}

Scene hairlines(unsigned seed, int n) {
    return generate(seed, n, [](Rng& rng, Scene& s, int i, Point a) {
        const auto near = [&] { return a + Vec2{rng.uniform(-60, 60), rng.uniform(-60, 60)}; };
        Path p;
        p.move_to(a);
        if (i % 2)
            p.line_to(near());
        else
            p.cubic_to(near(), near(), near());
        add_stroke(s, std::move(p), rng.color(1), 1.0);
    });
}

Scene glyph_shapes(unsigned seed, int n) {
    return generate(seed, n, [](Rng& rng, Scene& s, int i, Point c) {
        const double h = rng.uniform(8, 16);
        Path p;
        if (i % 2) { // an "o": a ring, the hole wound the other way
            ellipse(p, c, 0.35 * h, 0.5 * h, true);
            ellipse(p, c, 0.2 * h, 0.35 * h, false);
        } else { // an "s"-like band of quadratics
            const double w = 0.3 * h, t = 0.09 * h;
            p.move_to(c + Vec2{w, -0.5 * h});
            p.quad_to(c + Vec2{-w, -0.5 * h}, c + Vec2{-w, -0.2 * h});
            p.quad_to(c + Vec2{w, 0}, c + Vec2{w, 0.25 * h});
            p.quad_to(c + Vec2{w, 0.5 * h}, c + Vec2{-w, 0.5 * h});
            p.line_to(c + Vec2{-w, 0.5 * h - t});
            p.quad_to(c + Vec2{w - t, 0.5 * h - t}, c + Vec2{w - t, 0.25 * h});
            p.quad_to(c + Vec2{-w - t, 0}, c + Vec2{-w - t, -0.2 * h});
            p.quad_to(c + Vec2{-w - t, -0.5 * h - t}, c + Vec2{w, -0.5 * h - t});
            p.close();
        }
        add_fill(s, std::move(p), {0, 0, 0, 1});
    });
}

Scene full_canvas_rect() {
    Scene s = empty_scene();
    add_fill(s, rect({0, 0}, {kSceneSize, kSceneSize}), {0, 0.5f, 0.5f, 1});
    return s;
}

Scene stretched_image(unsigned seed, int side, bool turned) {
    // Smooth ramps and noise, opaque: what a photograph asks of the sampler.
    Rng rng(seed);
    auto im = std::make_shared<RasterImage>();
    im->width = im->height = side;
    im->pixels.reserve(std::size_t(side) * std::size_t(side));
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            im->pixels.push_back({float(x) / side, float(y) / side, float(rng.uniform(0, 1)), 1});
    auto pattern = std::make_shared<Pattern>();
    pattern->width = pattern->height = kSceneSize;
    pattern->image = std::move(im);
    pattern->repeat = false;
    // Turned: grown by 20% about the centre, so that the turned image still
    // covers the canvas.
    const Vec2 centre{kSceneSize / 2, kSceneSize / 2};
    if (turned)
        pattern->transform = Affine::translate(centre) * Affine::rotate(std::numbers::pi / 18) *
                             Affine::scale(1.2) * Affine::translate(-centre);
    Scene s = empty_scene();
    add_painted(s, rect({0, 0}, {kSceneSize, kSceneSize}),
                Fill{{}, nullptr, 1, FillRule::NonZero, pattern});
    return s;
}

Scene gradient_fill(Gradient::Kind kind) {
    auto g = std::make_shared<Gradient>();
    g->kind = kind;
    g->p1 = {0, 0}, g->p2 = {1, 1};
    g->focal = {0.3, 0.3};
    g->stops = {{0, {1, 0, 0, 1}}, {0.5f, {0, 1, 0, 1}}, {1, {0, 0, 1, 1}}};
    Scene s = empty_scene();
    add_painted(s, rect({0, 0}, {kSceneSize, kSceneSize}), Fill{{}, std::move(g)});
    return s;
}

Scene pattern_rects(unsigned seed, int n) {
    auto tile = std::make_shared<Pattern>();
    tile->width = tile->height = 16;
    Scene content = empty_scene();
    add_fill(content, rect({0, 0}, {16, 16}), {0.93f, 0.93f, 0.93f, 1});
    Path disc;
    ellipse(disc, {8, 8}, 5, 5, true);
    add_fill(content, std::move(disc), {0.8f, 0.1f, 0.1f, 1});
    Path cross;
    cross.move_to({0, 0});
    cross.line_to({16, 16});
    cross.move_to({16, 0});
    cross.line_to({0, 16});
    add_stroke(content, std::move(cross), {0.2f, 0.2f, 0.2f, 1}, 1.5);
    tile->content = std::move(content.root);
    return generate(seed, n, [&](Rng& rng, Scene& s, int, Point a) {
        const Vec2 size{rng.uniform(10, 64), rng.uniform(10, 64)};
        add_painted(s, rect(a, a + size), Fill{{}, nullptr, 1, FillRule::NonZero, tile});
    });
}

std::vector<NamedScene> standard_scenes() {
    std::vector<NamedScene> v;
    v.push_back({"blobs_2k", random_blobs(1, 2000)});
    v.push_back({"blobs_20k", random_blobs(2, 20000)});
    v.push_back({"ellipse", large_ellipse()});
    v.push_back({"hairlines_10k", hairlines(3, 10000)});
    v.push_back({"glyphs_5k", glyph_shapes(4, 5000)});
    v.push_back({"full_canvas_rect", full_canvas_rect()});
    return v;
}

std::vector<NamedScene> paint_scenes() {
    std::vector<NamedScene> v;
    v.push_back({"image_level", stretched_image(5, 512, false)});
    v.push_back({"image_turned", stretched_image(5, 512, true)});
    v.push_back({"image_shrunk", stretched_image(5, 2900, false)});
    v.push_back({"linear_gradient", gradient_fill(Gradient::Kind::Linear)});
    v.push_back({"radial_gradient", gradient_fill(Gradient::Kind::Radial)});
    v.push_back({"pattern_2k", pattern_rects(6, 2000)});
    return v;
}

} // namespace casteljau::bench
