// The measured error of a mesh against its patches, in pixels.
//
// For each triangle and each point of a barycentric lattice of order 6 (the
// edge midpoints, the centroid and 22 more), the point T = sum b_a V_a of the
// triangle and the surface point S(sum b_a w_a) at the interpolated (u, v)
// are projected, and their pixel distance taken; the result is the largest.
// Only triangles in front of the near plane and overlapping the image count:
// the rest are never seen. This is the figure the tests hold to the
// tolerance and `casteljau patch --stats` reports as max_error_px.
#pragma once

#include "casteljau/patch/patch_model.h"
#include "casteljau/tessellate/mesh.h"
#include "casteljau/tessellate/projection.h"

namespace casteljau {

double measure_max_error_px(const PatchModel& model, const Mesh& mesh,
                            const ScreenProjection& view);

} // namespace casteljau
