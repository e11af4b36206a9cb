// Textbook recursive subdivision, kept as the baseline the adaptive flattener
// is measured against (it is what Cairo's and AGG's flatteners do).
//
// A piece is emitted when every control point lies within tol of its chord
// segment (the hull bound of flatness.h, which guarantees the curve does too);
// otherwise it is halved by de Casteljau at t = 1/2. The recursion runs over an
// explicit stack of fixed size: depth-first with the right half pushed first,
// the stack holds at most one pending right half per level, so kMaxDepth + 1
// entries suffice. Pieces at depth kMaxDepth are emitted whatever their
// flatness (2^-24 of the parameter range: only reached when the tolerance is
// below the coordinates' rounding noise), so a curve gives at most 2^24
// segments.
#pragma once

#include "casteljau/flatten/flatness.h"
#include "casteljau/flatten/vertex.h"
#include "casteljau/geom/fixed_stack.h"

namespace casteljau {

inline constexpr int kHalvingMaxDepth = 24;

template <class Curve, class Sink>
void flatten_halving(const Curve& c, double tolerance, Sink&& sink) noexcept {
    struct Piece {
        Curve c;
        double t0, t1;
        int depth;
    };
    FixedStack<Piece, kHalvingMaxDepth + 1> stack;
    stack.push({c, 0.0, 1.0, 0});
    while (!stack.empty()) {
        const Piece piece = stack.pop();
        if (piece.depth == kHalvingMaxDepth || hull_deviation(piece.c) <= tolerance) {
            sink(FlatVertex{piece.c.end(), piece.t1});
            continue;
        }
        const auto halves = piece.c.split(0.5);
        const double tm = 0.5 * (piece.t0 + piece.t1);
        stack.push({halves[1], tm, piece.t1, piece.depth + 1});
        stack.push({halves[0], piece.t0, tm, piece.depth + 1});
    }
}

} // namespace casteljau
