// Surfaces built for the patch and tessellation tests and benchmarks.
#pragma once

#include "casteljau/patch/bspline_patch.h"
#include "casteljau/patch/patch_model.h"
#include "casteljau/tessellate/mesh.h"

#include <cstddef>
#include <random>

namespace casteljau::test {

// A patch with control points uniform in [-scale, scale]^3 and (s, t) in [0, 1]^2.
template <class Patch>
Patch random_patch(std::mt19937& rng, double scale = 100) {
    std::uniform_real_distribution<double> x(-scale, scale), s(0, 1);
    Patch p;
    for (auto& row : p.c)
        for (PatchPoint& q : row) q = {{x(rng), x(rng), x(rng)}, {s(rng), s(rng)}};
    return p;
}

// The unit sphere (centre 0, radius about 1) as 8 bicubic patches, four per
// hemisphere, each with a pole where its last row collapses to a point, as on
// the teapot's lid. du x dv points outward; neighbours share control points.
PatchModel sphere_model();

// A Quake-style arch: a 5 x 9 biquadratic grid (2 x 4 patches) bent into a
// half-cylinder with texture coordinates.
PatchModel arch_model();

// Uneven curvature: a flat 8 x 8 B-spline grid (25 pieces) with one tall,
// narrow bump, stored as Bezier pieces.
PatchModel bump_model();

// Mesh topology after welding vertices by exact position; triangles whose
// corners weld to fewer than three points are ignored.
struct Topology {
    std::size_t edges = 0;
    std::size_t boundary_edges = 0; // used by one triangle
    std::size_t overused_edges = 0; // used by more than two
    std::size_t t_junctions = 0;    // vertices strictly inside a boundary edge
};
Topology mesh_topology(const Mesh& mesh);

} // namespace casteljau::test
