// Piecewise cubic Bezier editing with anchors and handles, the model of the
// pen tools of drawing applications.
//
// Anchor i is the on-curve point where segment i - 1 ends and segment i
// starts; its handles are the off-curve points next to it: `in` (the third
// control point of segment i - 1) and `out` (the second of segment i). Since
// a cubic's end derivatives are 3 (p3 - p2) and 3 (p1 - p0), a joint is
//   G1 (smooth)     when in and out lie on opposite sides of the anchor on one line,
//   C1 (symmetric)  when in - anchor = -(out - anchor),
// and the editing operations keep the joint's mode:
// * moving an anchor moves its two handles with it (the joint's shape is kept);
// * moving a handle of a smooth joint turns its twin to the opposite
//   direction, keeping the twin's length; of a symmetric joint, mirrors it;
//   of a corner, leaves the twin alone;
// * setting a mode aligns the handles along the direction from `in` to `out`
//   (smooth keeps each length, symmetric takes their mean).
// A handle on its anchor has no direction: then the twin is left alone.
// continuity() measures what the geometry is (C0, G1, C1 or C2, with
// joint_continuity), independently of the mode that produced it.
//
// Conversion from a subpath: lines become cubics with handles at their thirds
// (same curve, same parameterisation), quadratics are degree-elevated (exact),
// and conics are halved, each half replaced by the cubic with the same end
// tangents whose handles are at 4w / (3 (1 + w)) of the way to the control
// point (exact at the middle for circular arcs; a quarter circle's halves
// deviate by about 4e-6 of the radius). Joint modes are inferred from the
// measured continuity.
#pragma once

#include "casteljau/curve/path.h"

#include <cstddef>
#include <vector>

namespace casteljau {

/// How an anchor ties its two handles together.
enum class JointMode {
    Corner,   ///< handles move independently
    Smooth,   ///< handles stay on one line through the anchor (G1)
    Symmetric ///< handles mirror each other through the anchor (C1)
};

/// Which of an anchor's two handles.
enum class HandleSide {
    In, ///< the handle before the anchor, on the incoming segment
    Out ///< the handle after the anchor, on the outgoing segment
};

/// An on-curve point with its two off-curve handles and its joint mode.
struct Anchor {
    Point point;                        ///< on the curve
    Point in;                           ///< incoming handle (unused at an open start)
    Point out;                          ///< outgoing handle (unused at an open end)
    JointMode mode = JointMode::Corner; ///< how moves keep in and out together
};

/// A subpath of cubic segments edited through its anchors and handles.
class BezierSpline {
  public:
    /// An empty spline (no anchors).
    BezierSpline() = default;
    /// The spline of a subpath (see the conversion rules above).
    static BezierSpline from_subpath(const Subpath& sp);
    /// The spline as a subpath of cubic segments.
    Subpath to_subpath() const;

    /// Appends an anchor; with the previous one it bounds a new segment.
    void add_anchor(const Anchor& a) { anchors_.push_back(a); }
    /// Makes the spline a loop (the last anchor joins the first) or not.
    void set_closed(bool closed) { closed_ = closed; }
    /// Whether the last anchor joins the first.
    bool closed() const { return closed_; }
    /// Number of anchors.
    std::size_t anchor_count() const { return anchors_.size(); }
    /// Anchor i (i < anchor_count()).
    const Anchor& anchor(std::size_t i) const { return anchors_[i]; }
    /// Number of segments: anchors - 1 when open, anchors when closed.
    std::size_t segment_count() const;
    /// Segment i, from anchor i to anchor i + 1 (mod the count when closed).
    CubicBez segment(std::size_t i) const;
    /// Whether anchor i joins two segments (every anchor but an open spline's ends).
    bool is_joint(std::size_t i) const;

    /// Moves anchor i to `p`, its handles with it.
    void move_anchor(std::size_t i, Point p);
    /// Moves one handle of anchor i to `p`; the twin follows the joint's mode.
    void move_handle(std::size_t i, HandleSide side, Point p);
    /// Sets the joint mode of anchor i and aligns its handles to it.
    void set_mode(std::size_t i, JointMode mode);
    /// Measured continuity at anchor i; Continuity::None where is_joint(i) is false.
    Continuity continuity(std::size_t i, double tol = 1e-9) const;

  private:
    std::vector<Anchor> anchors_;
    bool closed_ = false;
};

} // namespace casteljau
