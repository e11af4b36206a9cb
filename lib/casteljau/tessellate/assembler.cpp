#include "casteljau/tessellate/assembler.h"

#include "casteljau/curve/decasteljau.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace casteljau {

namespace {

bool less(Point3 a, Point3 b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

} // namespace

EdgeRef MeshAssembler::edge(std::span<const PatchPoint> curve) {
    Edge e;
    e.count = std::uint32_t(curve.size());
    for (std::uint32_t i = 0; i < e.count; ++i) e.p[i] = curve[i].p;
    // Reverse when the far end is smaller; a palindrome is its own reverse.
    bool reversed = false;
    for (std::uint32_t i = 0, j = e.count - 1; i < j; ++i, --j) {
        if (e.p[i] == e.p[j]) continue;
        reversed = less(e.p[j], e.p[i]);
        break;
    }
    if (reversed) std::reverse(e.p.begin(), e.p.begin() + e.count);
    e.collapsed =
        std::all_of(e.p.begin(), e.p.begin() + e.count, [&](Point3 q) { return q == e.p[0]; });
    std::array<double, 13> key{};
    key[0] = e.count;
    for (std::uint32_t i = 0; i < e.count; ++i) {
        key[1 + 3 * i] = e.p[i].x;
        key[2 + 3 * i] = e.p[i].y;
        key[3 + 3 * i] = e.p[i].z;
    }
    const auto [it, inserted] = edge_ids_.try_emplace(key, std::uint32_t(edges_.size()));
    if (inserted) edges_.push_back(e);
    return {it->second, reversed};
}

Point3 MeshAssembler::edge_point(EdgeRef ref, std::uint32_t k, std::uint32_t n) const {
    const Edge& e = edges_[ref.id];
    if (e.collapsed) return e.p[0];
    const double t = double(canonical(ref, k, n)) / double(n);
    return decasteljau_eval(std::span<const Point3>(e.p.data(), e.count), t);
}

bool MeshAssembler::WeldKey::operator==(const WeldKey& o) const {
    return std::memcmp(v, o.v, sizeof v) == 0;
}

std::size_t MeshAssembler::WeldHash::operator()(const WeldKey& k) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (double d : k.v) h = (h ^ std::bit_cast<std::uint64_t>(d)) * 0x100000001b3ull;
    return std::size_t(h ^ (h >> 29));
}

std::uint32_t MeshAssembler::vertex(Point3 p, Vec3 normal, Point st) {
    // +0.0 for -0.0, so that the bitwise key agrees with ==.
    const WeldKey key{{p.x + 0.0, p.y + 0.0, p.z + 0.0, st.x + 0.0, st.y + 0.0}};
    const auto [it, inserted] = weld_.try_emplace(key, std::uint32_t(mesh_.positions.size()));
    if (inserted) {
        mesh_.positions.push_back(p);
        mesh_.normals.push_back(normal);
        mesh_.st.push_back(st);
    }
    return it->second;
}

void MeshAssembler::triangle(std::array<std::uint32_t, 3> v, const TriangleSource& source) {
    // Two corners in one place (at a pole, possibly with different (s, t)):
    // the triangle covers nothing.
    const auto& p = mesh_.positions;
    if (p[v[0]] == p[v[1]] || p[v[1]] == p[v[2]] || p[v[2]] == p[v[0]]) return;
    mesh_.triangles.push_back(v);
    mesh_.sources.push_back(source);
}

} // namespace casteljau
