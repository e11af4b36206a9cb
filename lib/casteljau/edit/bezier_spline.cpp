#include "casteljau/edit/bezier_spline.h"

#include <variant>

namespace casteljau {

namespace {

// The cubic with the conic's end tangents, handles at 4w / (3 (1 + w)) of the
// way from each end to the control point: for a circular arc of angle a
// (w = cos(a/2)) that is the handle length 4/3 tan(a/4) r, exact at t = 1/2.
CubicBez conic_as_cubic(const Conic& c) {
    const double k = 4.0 * c.w / (3.0 * (1.0 + c.w));
    return {c.p0, c.p0 + (c.p1 - c.p0) * k, c.p2 + (c.p1 - c.p2) * k, c.p2};
}

void append_as_cubics(const Segment& s, std::vector<CubicBez>& out) {
    if (const auto* l = std::get_if<Line>(&s))
        out.push_back(
            {l->p[0], lerp(l->p[0], l->p[1], 1.0 / 3), lerp(l->p[0], l->p[1], 2.0 / 3), l->p[1]});
    else if (const auto* q = std::get_if<QuadBez>(&s))
        out.push_back(q->elevate());
    else if (const auto* c = std::get_if<CubicBez>(&s))
        out.push_back(*c);
    else
        for (const Conic& half : std::get<Conic>(s).split(0.5)) out.push_back(conic_as_cubic(half));
}

JointMode mode_of(Continuity c) {
    if (c >= Continuity::C1) return JointMode::Symmetric;
    return c == Continuity::G1 ? JointMode::Smooth : JointMode::Corner;
}

} // namespace

BezierSpline BezierSpline::from_subpath(const Subpath& sp) {
    std::vector<CubicBez> cubics;
    for (const Segment& s : sp.segments) append_as_cubics(s, cubics);
    BezierSpline spline;
    spline.anchors_.push_back({sp.start, sp.start, sp.start, JointMode::Corner});
    for (const CubicBez& c : cubics) {
        spline.anchors_.back().out = c.p[1];
        spline.anchors_.push_back({c.p[3], c.p[2], c.p[3], JointMode::Corner});
    }
    // A closed subpath's segments form a loop: its last anchor is its first.
    if (sp.closed && spline.anchors_.size() > 2) {
        spline.anchors_.front().in = spline.anchors_.back().in;
        spline.anchors_.pop_back();
        spline.closed_ = true;
    }
    for (std::size_t i = 0; i < spline.anchors_.size(); ++i)
        spline.anchors_[i].mode = mode_of(spline.continuity(i));
    return spline;
}

Subpath BezierSpline::to_subpath() const {
    Subpath sp;
    if (anchors_.empty()) return sp;
    sp.start = anchors_.front().point;
    sp.closed = closed_;
    for (std::size_t i = 0; i < segment_count(); ++i) sp.segments.push_back(segment(i));
    return sp;
}

std::size_t BezierSpline::segment_count() const {
    if (anchors_.size() < 2) return 0;
    return closed_ ? anchors_.size() : anchors_.size() - 1;
}

CubicBez BezierSpline::segment(std::size_t i) const {
    const Anchor& a = anchors_[i];
    const Anchor& b = anchors_[(i + 1) % anchors_.size()];
    return {a.point, a.out, b.in, b.point};
}

bool BezierSpline::is_joint(std::size_t i) const {
    if (anchors_.size() < 2) return false;
    return closed_ || (i > 0 && i + 1 < anchors_.size());
}

void BezierSpline::move_anchor(std::size_t i, Point p) {
    Anchor& a = anchors_[i];
    const Vec2 by = p - a.point;
    a.point = p;
    a.in += by;
    a.out += by;
}

void BezierSpline::move_handle(std::size_t i, HandleSide side, Point p) {
    Anchor& a = anchors_[i];
    Point& moved = side == HandleSide::In ? a.in : a.out;
    Point& twin = side == HandleSide::In ? a.out : a.in;
    moved = p;
    const Vec2 arm = p - a.point;
    if (!is_joint(i) || a.mode == JointMode::Corner || arm.length_sq() == 0.0) return;
    if (a.mode == JointMode::Symmetric)
        twin = a.point - arm;
    else
        twin = a.point - arm.normalized() * (twin - a.point).length();
}

void BezierSpline::set_mode(std::size_t i, JointMode mode) {
    Anchor& a = anchors_[i];
    a.mode = mode;
    const Vec2 along = a.out - a.in;
    if (!is_joint(i) || mode == JointMode::Corner || along.length_sq() == 0.0) return;
    const Vec2 dir = along.normalized();
    double in_len = (a.in - a.point).length(), out_len = (a.out - a.point).length();
    if (mode == JointMode::Symmetric) in_len = out_len = 0.5 * (in_len + out_len);
    a.in = a.point - dir * in_len;
    a.out = a.point + dir * out_len;
}

Continuity BezierSpline::continuity(std::size_t i, double tol) const {
    if (!is_joint(i)) return Continuity::None;
    const std::size_t before = i == 0 ? anchors_.size() - 1 : i - 1;
    return joint_continuity(segment(before), segment(i), tol);
}

} // namespace casteljau
