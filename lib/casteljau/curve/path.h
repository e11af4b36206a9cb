// Path: the 2D drawing API. A path is a list of subpaths; a subpath is a start
// point and a chain of segments (lines, quadratics, cubics, conics), each
// starting where the previous one ended, optionally closed.
//
// Semantics follow SVG and the HTML canvas: a drawing command with no open
// subpath starts one at the current point (the origin at first, the start of
// the last closed subpath after close()); close() adds the closing line when
// the subpath does not already end at its start, so a closed subpath's
// segments form a loop; arc_to takes SVG arc parameters and appends exact
// conics.
//
// Each subpath has the global parameterisation of a piecewise curve:
// x(u) = x_i(u - i) for u in [i, i+1], i = 0..segments-1.
#pragma once

#include "casteljau/curve/bez.h"
#include "casteljau/curve/conic.h"

#include <cstddef>
#include <optional>
#include <variant>
#include <vector>

namespace casteljau {

using Segment = std::variant<Line, QuadBez, CubicBez, Conic>;

Point segment_start(const Segment& s);
Point segment_end(const Segment& s);
Point segment_eval(const Segment& s, double t);
Vec2 segment_deriv(const Segment& s, double t);
Vec2 segment_deriv2(const Segment& s, double t);
/// Direction in which the segment leaves its start / arrives at its end; where
/// the derivative vanishes (coincident control points) the limit direction is
/// used. Zero only for a segment collapsed to a point.
Vec2 segment_start_tangent(const Segment& s);
Vec2 segment_end_tangent(const Segment& s);
Rect segment_bounds(const Segment& s);
Rect segment_control_bounds(const Segment& s); ///< holds the segment (convex hull property)
Segment segment_subsegment(const Segment& s, double t0, double t1);
Segment segment_transformed(const Segment& s, const Affine& m);

/// A start point and a chain of segments, each starting where the last ended.
struct Subpath {
    Point start;
    std::vector<Segment> segments;
    bool closed = false;
};

/// The line that closes a subpath for filling (SVG 1.1, 11.3): from its end
/// back to its start, when it is open and does not end at its start.
std::optional<Line> fill_closing_line(const Subpath& sp);

/// How smoothly one segment joins the next, from weakest to strongest; each
/// level implies the ones before it (G1: same position and unit tangent; C1:
/// same first derivative; C2: same first and second derivatives).
enum class Continuity { None, C0, G1, C1, C2 };
const char* to_string(Continuity c);

/// Classifies the joint a(1) -> b(0). `tol` is relative to the size of the
/// quantities compared (positions to the segments' extent, derivatives to
/// their own length): a joint is C1 if |a'(1) - b'(0)| <= tol * max(1, |a'(1)|).
Continuity joint_continuity(const Segment& a, const Segment& b, double tol = 1e-9);

/// The 2D drawing API: subpaths of lines, quadratics, cubics and conics.
class Path {
  public:
    /// Starts a new subpath at p.
    void move_to(Point p);
    /// Appends a line from the current point to p.
    void line_to(Point p);
    /// Appends a quadratic with control point c ending at p.
    void quad_to(Point c, Point p);
    /// Appends a cubic with control points c1, c2 ending at p.
    void cubic_to(Point c1, Point c2, Point p);
    /// Appends a conic with control point c and weight w (> 0) ending at p.
    void conic_to(Point c, Point p, double w);
    /// SVG elliptical arc from the current point (appendix F.6): exact conics.
    void arc_to(Vec2 radii, double x_rotation_deg, bool large_arc, bool sweep, Point p);
    /// Closes the subpath (adding the closing line when it does not end at its start).
    void close();
    /// Appends a segment as it is. It should start at the current point; with
    /// no open subpath, one starts at the segment's start.
    void append(const Segment& s);
    /// Appends a whole subpath (e.g. one built by BezierSpline::to_subpath or
    /// interpolate_c2) as move_to, its segments, and close() when it is closed.
    void add_subpath(const Subpath& sp);
    /// The same, taking the segments' storage: one allocation, the caller's,
    /// where appending them one by one grows the vector step by step (a text
    /// of 1e5 one-glyph tspans held 250 MB of glyph outlines, 172 MB taken
    /// whole). Reserve one segment more for a closed subpath whose end is not
    /// its start: close() adds the closing line.
    void add_subpath(Subpath&& sp);

    /// Where the next segment starts.
    Point current_point() const { return current_; }
    /// The subpaths, in drawing order.
    const std::vector<Subpath>& subpaths() const { return subpaths_; }
    /// Whether the path has no subpath.
    bool empty() const { return subpaths_.empty(); }
    /// Total number of segments over all subpaths.
    std::size_t segment_count() const;

    /// Maps every segment by m (exact: control points are mapped).
    void transform(const Affine& m);
    /// Tight bounds (curve extrema), and the cheaper bounds of all control
    /// points, which contain the path too (convex hull property).
    Rect bounds() const;
    /// Box of the control points, which holds the curve (convex hull
    /// property). Kept as the path is built: the renderer asks for it per
    /// shape and band.
    Rect control_bounds() const;

    /// The subpath's global parameterisation; u is clamped to [0, segments].
    Point eval(std::size_t subpath, double u) const;
    /// Continuity of every joint of a subpath: joint i is segment i -> i+1; a
    /// closed subpath has one more, last -> first.
    std::vector<Continuity> continuity(std::size_t subpath, double tol = 1e-9) const;

  private:
    std::vector<Subpath> subpaths_;
    /// control_bounds() of every subpath but a last one with no segment yet
    /// (a lone move_to, which the next move_to drops). Kept in the path
    /// object, so that reading it touches none of the segments' storage.
    Rect control_box_ = Rect::empty();
    Point current_{};
    bool open_ = false;       ///< the last subpath accepts segments
    bool lone_start_ = false; ///< the last subpath has no segment yet; it starts at current_
};

} // namespace casteljau
