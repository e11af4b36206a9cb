#include "casteljau/curve/path.h"

#include "casteljau/curve/arc.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace casteljau {

namespace {

// The first nonzero control-polygon leg seen from the end: it is the
// direction of the first nonvanishing derivative there (for conics too: the
// weights do not change the end tangents).
Vec2 polygon_tangent(std::span<const Point> p, bool at_start) {
    const std::size_t n = p.size() - 1;
    for (std::size_t k = 1; k <= n; ++k) {
        const Vec2 v = at_start ? p[k] - p[0] : p[n] - p[n - k];
        if (v.length_sq() > 0.0) return v;
    }
    return {};
}

template <class F>
auto visit_curve(const Segment& s, F&& f) {
    return std::visit(std::forward<F>(f), s);
}

} // namespace

Point segment_start(const Segment& s) {
    return visit_curve(s, [](const auto& c) { return c.start(); });
}
Point segment_end(const Segment& s) {
    return visit_curve(s, [](const auto& c) { return c.end(); });
}
Point segment_eval(const Segment& s, double t) {
    return visit_curve(s, [t](const auto& c) { return c.eval(t); });
}
Vec2 segment_deriv(const Segment& s, double t) {
    return visit_curve(s, [t](const auto& c) { return c.deriv(t); });
}
Vec2 segment_deriv2(const Segment& s, double t) {
    return visit_curve(s, [t](const auto& c) { return c.deriv2(t); });
}
Rect segment_bounds(const Segment& s) {
    return visit_curve(s, [](const auto& c) { return c.bounds(); });
}
Rect segment_control_bounds(const Segment& s) {
    return visit_curve(s, [](const auto& c) { return c.control_bounds(); });
}
Segment segment_subsegment(const Segment& s, double t0, double t1) {
    return visit_curve(s, [=](const auto& c) -> Segment { return c.subsegment(t0, t1); });
}
Segment segment_transformed(const Segment& s, const Affine& m) {
    return visit_curve(s, [&m](const auto& c) -> Segment { return c.transformed(m); });
}

namespace {
Vec2 segment_tangent(const Segment& s, bool at_start) {
    return visit_curve(
        s, [at_start](const auto& c) { return polygon_tangent(c.control_points(), at_start); });
}
} // namespace

Vec2 segment_start_tangent(const Segment& s) { return segment_tangent(s, true); }
Vec2 segment_end_tangent(const Segment& s) { return segment_tangent(s, false); }

const char* to_string(Continuity c) {
    switch (c) {
    case Continuity::None:
        return "none";
    case Continuity::C0:
        return "C0";
    case Continuity::G1:
        return "G1";
    case Continuity::C1:
        return "C1";
    case Continuity::C2:
        return "C2";
    }
    return "?";
}

Continuity joint_continuity(const Segment& a, const Segment& b, double tol) {
    const auto close = [tol](Vec2 d, double scale) {
        return d.length() <= tol * std::max(1.0, scale);
    };
    const Rect box = segment_bounds(a).united(segment_bounds(b));
    if (!close(segment_start(b) - segment_end(a), std::max(box.width(), box.height())))
        return Continuity::None;
    const Vec2 ta = segment_end_tangent(a), tb = segment_start_tangent(b);
    if (ta.length_sq() == 0.0 || tb.length_sq() == 0.0) return Continuity::C0;
    // G1: same unit tangent (so also the same direction, not opposite).
    if (!close(tb.normalized() - ta.normalized(), 1.0)) return Continuity::C0;
    const Vec2 da = segment_deriv(a, 1.0), db = segment_deriv(b, 0.0);
    if (!close(db - da, da.length())) return Continuity::G1;
    const Vec2 dda = segment_deriv2(a, 1.0), ddb = segment_deriv2(b, 0.0);
    if (!close(ddb - dda, dda.length())) return Continuity::C1;
    return Continuity::C2;
}

namespace {

// The box of a subpath's start and of its segments' boxes (`of`).
Rect subpath_box(const Subpath& s, Rect (*of)(const Segment&)) {
    Rect r = Rect::empty().united(s.start);
    for (const Segment& seg : s.segments) r = r.united(of(seg));
    return r;
}

} // namespace

void Path::append(const Segment& s) {
    if (!open_) {
        subpaths_.push_back({segment_start(s), {}, false});
        open_ = true;
    }
    Subpath& last = subpaths_.back();
    if (last.segments.empty()) control_box_ = control_box_.united(last.start);
    control_box_ = control_box_.united(segment_control_bounds(s));
    last.segments.push_back(s);
    lone_start_ = false;
    current_ = segment_end(s);
}

void Path::move_to(Point p) {
    // A lone move_to leaves no trace: an empty subpath would draw nothing.
    if (open_ && subpaths_.back().segments.empty()) subpaths_.pop_back();
    subpaths_.push_back({p, {}, false});
    open_ = true;
    lone_start_ = true;
    current_ = p;
}

void Path::line_to(Point p) {
    const Point from = current_;
    append(Line{from, p});
}
void Path::quad_to(Point c, Point p) {
    const Point from = current_;
    append(QuadBez{from, c, p});
}
void Path::cubic_to(Point c1, Point c2, Point p) {
    const Point from = current_;
    append(CubicBez{from, c1, c2, p});
}
void Path::conic_to(Point c, Point p, double w) {
    const Point from = current_;
    append(Conic{from, c, p, w});
}

void Path::arc_to(Vec2 radii, double x_rotation_deg, bool large_arc, bool sweep, Point p) {
    const SvgArcInput in{current_, p, radii, x_rotation_deg, large_arc, sweep};
    const EllipseArc arc = svg_arc(in);
    if (arc.kind == EllipseArc::Kind::Nothing) return;
    if (arc.kind == EllipseArc::Kind::Line) return line_to(p);
    std::array<Conic, 4> pieces;
    const int n = svg_arc_to_conics(in, pieces);
    for (int i = 0; i < n; ++i) append(pieces[i]);
}

std::optional<Line> fill_closing_line(const Subpath& sp) {
    if (sp.closed || sp.segments.empty()) return std::nullopt;
    const Point end = segment_end(sp.segments.back());
    if (end == sp.start) return std::nullopt;
    return Line{end, sp.start};
}

void Path::add_subpath(const Subpath& sp) { add_subpath(Subpath(sp)); }

void Path::add_subpath(Subpath&& sp) {
    move_to(sp.start);
    if (!sp.segments.empty()) {
        // What append() leaves, segment by segment: the box is a union, in any order.
        control_box_ = control_box_.united(subpath_box(sp, segment_control_bounds));
        current_ = segment_end(sp.segments.back());
        lone_start_ = false;
        subpaths_.back().segments = std::move(sp.segments);
    }
    if (sp.closed) close();
}

void Path::close() {
    if (!open_) return;
    Subpath& s = subpaths_.back();
    if (s.segments.empty()) {
        subpaths_.pop_back();
    } else {
        if (current_ != s.start) s.segments.push_back(Line{{current_, s.start}});
        s.closed = true;
    }
    current_ = subpaths_.empty() ? current_ : subpaths_.back().start;
    open_ = false;
    lone_start_ = false;
}

std::size_t Path::segment_count() const {
    std::size_t n = 0;
    for (const Subpath& s : subpaths_) n += s.segments.size();
    return n;
}

void Path::transform(const Affine& m) {
    for (Subpath& s : subpaths_) {
        s.start = m * s.start;
        for (Segment& seg : s.segments) seg = segment_transformed(seg, m);
    }
    control_box_ = Rect::empty();
    for (const Subpath& s : subpaths_)
        if (!s.segments.empty())
            control_box_ = control_box_.united(subpath_box(s, segment_control_bounds));
    current_ = m * current_;
}

Rect Path::bounds() const {
    Rect r = Rect::empty();
    for (const Subpath& s : subpaths_) r = r.united(subpath_box(s, segment_bounds));
    return r;
}

Rect Path::control_bounds() const {
    return lone_start_ ? control_box_.united(current_) : control_box_;
}

Point Path::eval(std::size_t subpath, double u) const {
    const Subpath& s = subpaths_[subpath];
    if (s.segments.empty()) return s.start;
    const double n = double(s.segments.size());
    u = std::clamp(u, 0.0, n);
    const std::size_t i = std::min(std::size_t(u), s.segments.size() - 1);
    return segment_eval(s.segments[i], u - double(i));
}

std::vector<Continuity> Path::continuity(std::size_t subpath, double tol) const {
    const Subpath& s = subpaths_[subpath];
    std::vector<Continuity> out;
    for (std::size_t i = 0; i + 1 < s.segments.size(); ++i)
        out.push_back(joint_continuity(s.segments[i], s.segments[i + 1], tol));
    if (s.closed && !s.segments.empty())
        out.push_back(joint_continuity(s.segments.back(), s.segments.front(), tol));
    return out;
}

} // namespace casteljau
