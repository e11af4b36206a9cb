// Mesh: the triangles a tessellator produces, and where each came from.
//
// Vertices carry position, unit normal (zero where the surface has none, as
// on a patch collapsed to a point) and texture coordinates (s, t). Triangles
// are counter-clockwise in the patch's (u, v) domain, so their geometric
// normal points along du x dv, the same way as the vertex normals.
// `sources` records, per triangle, its patch and the (u, v) of its corners:
// what the error measure compares the triangle against.
#pragma once

#include "casteljau/geom/point.h"
#include "casteljau/geom/point3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace casteljau {

/// Which patch a triangle came from, and its corners' (u, v) there.
struct TriangleSource {
    std::uint32_t patch = 0;
    std::array<Point, 3> uv{};
};

/// An indexed triangle mesh with normals and texture coordinates.
struct Mesh {
    std::vector<Point3> positions;
    std::vector<Vec3> normals;
    std::vector<Point> st;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<TriangleSource> sources;

    /// Empties the mesh, keeping its storage.
    void clear() {
        positions.clear();
        normals.clear();
        st.clear();
        triangles.clear();
        sources.clear();
    }
};

} // namespace casteljau
