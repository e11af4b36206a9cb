#include "bench_scenes.h"

#include <cmath>
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

void add_fill(Scene& s, Path p, Rgba color, FillRule rule = FillRule::NonZero) {
    Shape shape;
    shape.path = std::move(p);
    shape.fill = Fill{color, nullptr, 1, rule};
    s.root.children.push_back(Node{std::move(shape)});
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
    Path p;
    p.move_to({0, 0});
    p.line_to({kSceneSize, 0});
    p.line_to({kSceneSize, kSceneSize});
    p.line_to({0, kSceneSize});
    p.close();
    add_fill(s, std::move(p), {0, 0.5f, 0.5f, 1});
    return s;
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

} // namespace casteljau::bench
