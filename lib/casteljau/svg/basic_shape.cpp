#include "casteljau/svg/basic_shape.h"

#include "casteljau/curve/path_data.h"
#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/shapes.h"
#include "casteljau/svg/style.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

namespace casteljau {

using svg_detail::iequals;
using svg_detail::trim;
using svg_detail::words;

namespace {

// The pieces between top-level commas (none inside quotes).
std::vector<std::string_view> comma_list(std::string_view s) {
    std::vector<std::string_view> out;
    char quote = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (quote) {
            quote = s[i] == quote ? 0 : quote;
        } else if (s[i] == '"' || s[i] == '\'') {
            quote = s[i];
        } else if (s[i] == ',') {
            out.push_back(trim(s.substr(start, i - start)));
            start = i + 1;
        }
    }
    out.push_back(trim(s.substr(start)));
    return out;
}

// A <length-percentage>: a unit required but on 0 (CSS Values 4, 6.1).
std::optional<BoxLength> length_percentage(std::string_view w, const LengthContext& ctx) {
    std::string_view unit;
    const std::optional<double> v = parse_number(w, &unit);
    if (!v) return std::nullopt;
    if (unit == "%") return BoxLength{0, *v / 100};
    if (unit.empty()) return *v == 0 ? std::optional<BoxLength>(BoxLength{}) : std::nullopt;
    if (const auto len = parse_length(w, 0, ctx)) return BoxLength{*len, 0};
    return std::nullopt;
}

std::optional<BasicShape::Radius> radius(std::string_view w, const LengthContext& ctx) {
    using K = BasicShape::Radius::Kind;
    if (w == "closest-side") return BasicShape::Radius{K::ClosestSide, {}};
    if (w == "farthest-side") return BasicShape::Radius{K::FarthestSide, {}};
    const auto len = length_percentage(w, ctx);
    if (!len || len->px < 0 || len->fraction < 0) return std::nullopt;
    return BasicShape::Radius{K::Length, *len};
}

// 1 to 4 values spread over 4 as CSS's box shorthands do (top, right,
// bottom, left; or corners from the top-left).
bool four(const std::vector<std::string_view>& w, const LengthContext& ctx,
          std::array<BoxLength, 4>& out) {
    if (w.empty() || w.size() > 4) return false;
    std::array<BoxLength, 4> v;
    for (std::size_t i = 0; i < w.size(); ++i) {
        const auto len = length_percentage(w[i], ctx);
        if (!len) return false;
        v[i] = *len;
    }
    const std::size_t n = w.size();
    out = {v[0], n > 1 ? v[1] : v[0], n > 2 ? v[2] : v[0], n > 3 ? v[3] : n > 1 ? v[1] : v[0]};
    return true;
}

// circle() and ellipse(): radii, then `at` and a position.
bool circle_or_ellipse(std::string_view args, const LengthContext& ctx, BasicShape& s) {
    const std::vector<std::string_view> w = words(args);
    const auto at = std::find(w.begin(), w.end(), "at");
    const std::size_t radii = std::size_t(at - w.begin());
    const bool circle = s.kind == BasicShape::Kind::Circle;
    if (radii != 0 && radii != (circle ? 1u : 2u)) return false;
    for (std::size_t i = 0; i < radii; ++i) {
        const auto r = radius(w[i], ctx);
        if (!r) return false;
        s.radii[i] = *r;
    }
    if (at == w.end()) return true;
    if (w.end() - at - 1 < 1 || w.end() - at - 1 > 2) return false;
    std::string position(at[1]);
    if (at + 2 != w.end()) position.append(" ").append(at[2]);
    const std::optional<BoxPoint> p = parse_transform_origin(position, ctx);
    if (!p) return false;
    s.cx = {p->px.x, p->fraction.x}, s.cy = {p->px.y, p->fraction.y};
    return true;
}

bool inset(std::string_view args, const LengthContext& ctx, BasicShape& s) {
    std::vector<std::string_view> w = words(args);
    const auto round = std::find(w.begin(), w.end(), "round");
    if (!four({w.begin(), round}, ctx, s.inset)) return false;
    if (round == w.end()) return true;
    // Horizontal radii, then after a '/' (a word of its own or not) the vertical ones.
    std::string rest;
    for (auto it = round + 1; it != w.end(); ++it) rest.append(*it).append(" ");
    const std::size_t slash = rest.find('/');
    if (!four(words(std::string_view(rest).substr(0, slash)), ctx, s.round_x)) return false;
    if (slash == std::string::npos) {
        s.round_y = s.round_x;
        return true;
    }
    return four(words(std::string_view(rest).substr(slash + 1)), ctx, s.round_y);
}

// polygon() and path(): an optional fill rule first.
bool fill_rule_first(std::vector<std::string_view>& items, BasicShape& s) {
    if (items.front() == "nonzero" || items.front() == "evenodd") {
        s.fill_rule = items.front() == "evenodd" ? FillRule::EvenOdd : FillRule::NonZero;
        items.erase(items.begin());
    }
    return !items.empty();
}

bool polygon(std::string_view args, const LengthContext& ctx, BasicShape& s) {
    std::vector<std::string_view> items = comma_list(args);
    if (!fill_rule_first(items, s)) return false;
    for (const std::string_view item : items) {
        const std::vector<std::string_view> w = words(item);
        if (w.size() != 2) return false;
        const auto x = length_percentage(w[0], ctx), y = length_percentage(w[1], ctx);
        if (!x || !y) return false;
        s.points.push_back({*x, *y});
    }
    return true;
}

bool path(std::string_view args, BasicShape& s) {
    std::vector<std::string_view> items = comma_list(args);
    if (!fill_rule_first(items, s) || items.size() != 1) return false;
    const std::string_view str = items[0];
    if (str.size() < 2 || (str.front() != '"' && str.front() != '\'') || str.back() != str.front())
        return false;
    PathDataResult r = parse_path_data(str.substr(1, str.size() - 2));
    if (r.error) return false;
    s.path = std::move(r.path);
    return true;
}

std::optional<ShapeBox> geometry_box(std::string_view w) {
    if (w == "fill-box" || w == "content-box" || w == "padding-box") return ShapeBox::Fill;
    if (w == "stroke-box" || w == "border-box" || w == "margin-box") return ShapeBox::Stroke;
    if (w == "view-box") return ShapeBox::View;
    return std::nullopt;
}

} // namespace

std::optional<BasicShape> parse_basic_shape(std::string_view value, const LengthContext& ctx) {
    BasicShape s;
    bool have_box = false, have_shape = false;
    std::string_view v = trim(value);
    while (!v.empty()) {
        std::size_t name_end = 0;
        while (name_end < v.size() &&
               (std::isalnum(static_cast<unsigned char>(v[name_end])) || v[name_end] == '-'))
            ++name_end;
        const std::string_view name = v.substr(0, name_end);
        if (name_end < v.size() && v[name_end] == '(') {
            const std::size_t close = v.rfind(')');
            // One function at most; its arguments end at the last ')'
            // (path()'s string holds none) before any box keyword.
            const std::size_t end = v.find(')', name_end);
            if (have_shape || end == std::string_view::npos) return std::nullopt;
            const std::size_t last = name == "path" ? close : end;
            const std::string_view args = v.substr(name_end + 1, last - name_end - 1);
            using K = BasicShape::Kind;
            bool ok = false;
            if (iequals(name, "circle")) {
                s.kind = K::Circle;
                ok = circle_or_ellipse(args, ctx, s);
            } else if (iequals(name, "ellipse")) {
                s.kind = K::Ellipse;
                ok = circle_or_ellipse(args, ctx, s);
            } else if (iequals(name, "inset")) {
                s.kind = K::Inset, ok = inset(args, ctx, s);
            } else if (iequals(name, "polygon")) {
                s.kind = K::Polygon, ok = polygon(args, ctx, s);
            } else if (iequals(name, "path")) {
                s.kind = K::Path, ok = path(args, s);
            }
            if (!ok) return std::nullopt;
            have_shape = true;
            v = trim(v.substr(last + 1));
        } else {
            const std::optional<ShapeBox> box = geometry_box(name);
            if (!box || have_box || name_end == 0) return std::nullopt;
            s.box = *box, have_box = true;
            v = trim(v.substr(name_end));
        }
    }
    if (!have_box && !have_shape) return std::nullopt;
    return s;
}

namespace {

// inset()'s rectangle with elliptical corners, radii scaled down together
// where two on a side overlap (CSS Backgrounds 3, 5.5).
Path rounded_rect(const Rect& r, std::array<double, 4> rx, std::array<double, 4> ry) {
    const double w = r.width(), h = r.height();
    double f = 1;
    const auto fit = [&](double side, double a, double b) {
        if (a + b > side) f = std::min(f, side / (a + b));
    };
    fit(w, rx[0], rx[1]), fit(w, rx[3], rx[2]), fit(h, ry[0], ry[3]), fit(h, ry[1], ry[2]);
    for (int i = 0; i < 4; ++i) rx[std::size_t(i)] *= f, ry[std::size_t(i)] *= f;
    Path p;
    const auto corner = [&](std::size_t i, Point to) {
        p.arc_to({rx[i], ry[i]}, 0, false, true, to);
    };
    p.move_to({r.x0 + rx[0], r.y0});
    p.line_to({r.x1 - rx[1], r.y0});
    corner(1, {r.x1, r.y0 + ry[1]});
    p.line_to({r.x1, r.y1 - ry[2]});
    corner(2, {r.x1 - rx[2], r.y1});
    p.line_to({r.x0 + rx[3], r.y1});
    corner(3, {r.x0, r.y1 - ry[3]});
    p.line_to({r.x0, r.y0 + ry[0]});
    corner(0, {r.x0 + rx[0], r.y0});
    p.close();
    return p;
}

} // namespace

Path shape_path(const BasicShape& s, const Rect& box) {
    using K = BasicShape::Kind;
    const double w = box.width(), h = box.height();
    const Point c{box.x0 + s.cx.of(w), box.y0 + s.cy.of(h)};
    // A radius along x (side w), y (side h) or both (the diagonal).
    const auto radius = [&](const BasicShape::Radius& r, int axis) {
        const double dx[2] = {std::fabs(c.x - box.x0), std::fabs(box.x1 - c.x)};
        const double dy[2] = {std::fabs(c.y - box.y0), std::fabs(box.y1 - c.y)};
        using R = BasicShape::Radius::Kind;
        if (r.kind == R::Length)
            return r.length.of(axis == 0 ? w : axis == 1 ? h : std::hypot(w, h) / std::sqrt(2.0));
        const bool closest = r.kind == R::ClosestSide;
        const auto pick = [&](double a, double b) {
            return closest ? std::min(a, b) : std::max(a, b);
        };
        if (axis == 0) return pick(dx[0], dx[1]);
        if (axis == 1) return pick(dy[0], dy[1]);
        return pick(pick(dx[0], dx[1]), pick(dy[0], dy[1]));
    };
    switch (s.kind) {
    case K::Box:
        return rect_path(box.x0, box.y0, w, h, 0, 0);
    case K::Circle:
    case K::Ellipse: {
        const double rx = radius(s.radii[0], s.kind == K::Circle ? 2 : 0);
        const double ry = s.kind == K::Circle ? rx : radius(s.radii[1], 1);
        return rx > 0 && ry > 0 ? ellipse_path(c.x, c.y, rx, ry) : Path{};
    }
    case K::Inset: {
        const Rect r{box.x0 + s.inset[3].of(w), box.y0 + s.inset[0].of(h),
                     box.x1 - s.inset[1].of(w), box.y1 - s.inset[2].of(h)};
        if (!(r.width() > 0 && r.height() > 0)) return Path{};
        std::array<double, 4> rx, ry;
        for (std::size_t i = 0; i < 4; ++i) rx[i] = s.round_x[i].of(w), ry[i] = s.round_y[i].of(h);
        return rounded_rect(r, rx, ry);
    }
    case K::Polygon: {
        std::vector<Point> points;
        for (const auto& [x, y] : s.points) points.push_back({box.x0 + x.of(w), box.y0 + y.of(h)});
        return poly_path(points, true);
    }
    case K::Path: {
        Path p = s.path;
        p.transform(Affine::translate(box.min().to_vec()));
        return p;
    }
    }
    return Path{};
}

} // namespace casteljau
