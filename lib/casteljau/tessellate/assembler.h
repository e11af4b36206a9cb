// MeshAssembler: turns grid points of patches into shared mesh vertices, so
// that neighbouring patches meet without cracks.
//
// Why it is exact: a boundary curve shared by two patches has the same
// control points in both (Quake grids share the points; .bpt files repeat
// them), possibly in reverse order. Every boundary curve is put in a
// canonical orientation (the lexicographically smaller end first) and every
// point on it is evaluated from the canonical control points at the canonical
// parameter k/n, with k and n integers: both patches compute the same double
// from the same inputs, bit for bit. Vertices are then welded on their exact
// (position, s, t), so the shared points become shared indices; where the two
// patches disagree on (s, t) (a texture seam) the position is still the same.
// A boundary curve collapsed to one point (a pole) yields that point exactly.
//
// Triangles with two corners at one position (they occur at poles) are dropped.
#pragma once

#include "casteljau/patch/patch_point.h"
#include "casteljau/tessellate/mesh.h"

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <unordered_map>
#include <vector>

namespace casteljau {

/// A shared patch edge and the direction it is used in.
struct EdgeRef {
    std::uint32_t id = 0;
    bool reversed = false;
};

/// Builds a watertight Mesh: shared vertices and edges, welded across patches.
class MeshAssembler {
  public:
    /// Appends to `mesh`.
    explicit MeshAssembler(Mesh& mesh) : mesh_(mesh) {}

    /// The canonical identity of a boundary curve (2 to 4 control points, given
    /// in the patch's own orientation).
    EdgeRef edge(std::span<const PatchPoint> curve);
    /// The point at k / n along the edge, in the patch's orientation.
    Point3 edge_point(EdgeRef e, std::uint32_t k, std::uint32_t n) const;
    /// Canonical parameter of the patch-oriented k / n, and back.
    static std::uint32_t canonical(EdgeRef e, std::uint32_t k, std::uint32_t n) {
        return e.reversed ? n - k : k;
    }

    /// The index of the vertex at p (added when new), with its normal and texture coordinates.
    std::uint32_t vertex(Point3 p, Vec3 normal, Point st);
    /// Appends a triangle of vertex indices, with where it came from.
    void triangle(std::array<std::uint32_t, 3> v, const TriangleSource& source);

  private:
    struct Edge {
        std::array<Point3, 4> p{};
        std::uint32_t count = 0;
        bool collapsed = false;
    };
    struct WeldKey {
        double v[5];
        bool operator==(const WeldKey& o) const;
    };
    struct WeldHash {
        std::size_t operator()(const WeldKey& k) const;
    };

    Mesh& mesh_;
    std::vector<Edge> edges_;
    std::map<std::array<double, 13>, std::uint32_t> edge_ids_;
    std::unordered_map<WeldKey, std::uint32_t, WeldHash> weld_;
};

} // namespace casteljau
