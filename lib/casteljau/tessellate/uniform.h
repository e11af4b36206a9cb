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

namespace casteljau {

// Requires 1 <= steps_u, steps_v <= 65536. `out` is cleared first.
void tessellate_uniform(const PatchModel& model, int steps_u, int steps_v, Mesh& out);

} // namespace casteljau
