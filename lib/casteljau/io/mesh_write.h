// Writing a Mesh as Wavefront OBJ or PLY, atomically (atomic_file.h).
//
// * .obj: "v x y z", "vt s t", "vn x y z" per vertex and "f a/a/a b/b/b c/c/c"
//   per triangle (1-based, one index for all three attributes).
// * .ply: binary little-endian PLY 1.0, vertex properties x y z nx ny nz s t
//   as float, faces as a uchar-counted int list.
// Both keep the mesh's counter-clockwise winding (front faces along du x dv).
#pragma once

#include "casteljau/tessellate/mesh.h"

#include <string>

namespace casteljau {

/// The format follows the extension (.obj or .ply). Returns an empty string on
/// success, otherwise what went wrong (with the path).
std::string write_mesh_atomic(const std::string& path, const Mesh& mesh);

} // namespace casteljau
