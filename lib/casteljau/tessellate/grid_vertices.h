// GridVertices: the mesh vertex at the grid point (i / nu, j / nv) of one
// patch, computed once. Points on the patch boundary come from the shared
// edge (assembler.h), so a neighbour asking for the same point gets the same
// vertex; interior points are evaluated on the patch. Normals come from
// patch_normal (finite at poles), texture coordinates from the patch itself.
#pragma once

#include "casteljau/patch/normal.h"
#include "casteljau/tessellate/assembler.h"

#include <array>
#include <cstdint>
#include <unordered_map>

namespace casteljau {

/// Sides of the (u, v) square, counter-clockwise: v = 0, u = 1, v = 1, u = 0.
enum Side : int { kBottom = 0, kRight = 1, kTop = 2, kLeft = 3 };

/// The shared edges of a patch's four sides, in Side order.
template <class Patch>
std::array<EdgeRef, 4> boundary_edges(MeshAssembler& a, const Patch& patch) {
    return {a.edge(patch.c[0]), a.edge(patch.column(Patch::kDegreeU)), a.edge(patch.c.back()),
            a.edge(patch.column(0))};
}

/// Vertices of a patch's grid, shared along its boundary with its neighbours.
template <class Patch>
class GridVertices {
  public:
    /// The grid vertices of `patch`, numbered `patch_index` in the mesh.
    GridVertices(MeshAssembler& a, const Patch& patch, std::uint32_t patch_index)
        : a_(a), patch_(patch), index_(patch_index), size_(patch.control_bounds().diagonal()),
          edges_(boundary_edges(a, patch)) {}

    /// The patch's number in the mesh.
    std::uint32_t patch_index() const { return index_; }

    /// The vertex at grid point (i of nu, j of nv), added when new.
    std::uint32_t at(std::uint32_t i, std::uint32_t nu, std::uint32_t j, std::uint32_t nv) {
        const std::uint64_t key = (std::uint64_t(i) << 32) | j;
        const auto [it, inserted] = cache_.try_emplace(key, 0);
        if (!inserted) return it->second;
        const double u = double(i) / double(nu), v = double(j) / double(nv);
        const PatchDerivatives d = patch_.derivatives(u, v);
        Point3 p = d.point.p;
        if (j == 0)
            p = a_.edge_point(edges_[kBottom], i, nu);
        else if (j == nv)
            p = a_.edge_point(edges_[kTop], i, nu);
        else if (i == 0)
            p = a_.edge_point(edges_[kLeft], j, nv);
        else if (i == nu)
            p = a_.edge_point(edges_[kRight], j, nv);
        return it->second = a_.vertex(p, patch_normal(patch_, u, v, d, size_), d.point.st);
    }

    /// A vertex of the patch's interior that no other piece shares.
    std::uint32_t interior(double u, double v) {
        const PatchDerivatives d = patch_.derivatives(u, v);
        return a_.vertex(d.point.p, patch_normal(patch_, u, v, d, size_), d.point.st);
    }

  private:
    MeshAssembler& a_;
    const Patch& patch_;
    std::uint32_t index_;
    double size_;
    std::array<EdgeRef, 4> edges_;
    std::unordered_map<std::uint64_t, std::uint32_t> cache_;
};

} // namespace casteljau
