// Uniform tessellation: the baseline adaptive tessellation is measured against.
//
// Every patch becomes a steps_u x steps_v grid of surface points, the same
// for every patch, with two triangles per cell, both counter-clockwise in
// (u, v) (so both face along du x dv) and split along the same diagonal
// everywhere. Points on shared boundaries come from the shared edge
// (assembler.h), so neighbours meet exactly.
#pragma once

#include "casteljau/patch/patch_model.h"
#include "casteljau/tessellate/mesh.h"
#include "casteljau/tessellate/projection.h"

namespace casteljau {

/// Requires 1 <= steps_u, steps_v <= 65536. `out` is cleared first.
void tessellate_uniform(const PatchModel& model, int steps_u, int steps_v, Mesh& out);

/// Uniform at equal measured error: the fewest steps N (steps_u = steps_v = N,
/// 1 <= N <= max_steps) whose measured error (error.h) is at most
/// `max_error_px`, found by doubling and then bisection. The error falls as N
/// grows, up to rounding, so the result meets the bound and N - 1 does not;
/// max_steps when nothing meets it. `scratch` ends up holding some tried mesh.
int fewest_uniform_steps(const PatchModel& model, const ScreenProjection& view, double max_error_px,
                         int max_steps, Mesh& scratch);

} // namespace casteljau
