// Adaptive, watertight tessellation in screen space.
//
// Each patch is split in u or in v at the midpoint, over a fixed explicit
// stack, until the screen-space bound of screen_flatness.h is within the
// tolerance (pixels): every triangle then lies within `tolerance` px of the
// surface. The direction split is the one whose rows (columns) bend more; a
// piece that only twists is split across its wider side.
//
// Watertight, with no T-junctions: every piece is a dyadic rectangle of the
// patch's (u, v) square, with corners on a grid of 2^kMaxPatchDepth steps.
// A first pass records each piece's corners on the lines its sides lie on
// (iso-lines inside a patch, shared boundary curves between patches, in
// their canonical parameter, assembler.h); a second pass triangulates each
// piece as a fan around its centre through every recorded vertex on its
// sides, so a side that a smaller neighbour cut in two is cut in two on this
// side as well (stitching; Moreton 2001 reaches the same end by forward
// differencing). The fan needs no extra flatness: the bound holds for any
// triangles with corners on the piece. A piece with no extra vertices is two
// triangles, split along the shorter diagonal.
//
// Depth cap: kMaxPatchDepth halvings per direction (pieces of 2^-16 of the
// patch). A piece at the cap in both directions is emitted as it is; with a
// tolerance >= 1e-4 px and images <= 16384 px that is never reached by a
// patch of finite, in-front geometry. Pieces entirely behind the near plane
// or beside the image are not refined (they are not seen).
#pragma once

#include "casteljau/patch/patch_model.h"
#include "casteljau/tessellate/mesh.h"
#include "casteljau/tessellate/projection.h"

#include <cstddef>

namespace casteljau {

inline constexpr int kMaxPatchDepth = 16;

/// The piece budget: at most 16 pieces per pixel of the image, and at most
/// 2^20 (about 750 MB with the mesh, measured). Within it, pieces are as the bound asks;
/// once it is spent, every piece still to be looked at is emitted as it is,
/// like a piece at the depth cap, so the mesh stays watertight but no longer
/// meets the tolerance everywhere. The depth cap alone bounds a patch by
/// 2^32 pieces: geometry through the eye or near plane, which projects to
/// unbounded size, would otherwise take unbounded time and memory.
inline constexpr std::size_t kMaxPiecesPerPixel = 16;
inline constexpr std::size_t kMaxPieces = std::size_t(1) << 20;
std::size_t default_piece_budget(const ScreenProjection& view);

/// What an adaptive tessellation did.
struct AdaptiveStats {
    std::size_t pieces = 0;
    bool budget_reached = false; ///< some pieces may be off by more than the tolerance
};

/// `out` is cleared first.
AdaptiveStats tessellate_adaptive(const PatchModel& model, const ScreenProjection& view,
                                  double tolerance, Mesh& out);
AdaptiveStats tessellate_adaptive(const PatchModel& model, const ScreenProjection& view,
                                  double tolerance, std::size_t piece_budget, Mesh& out);

} // namespace casteljau
