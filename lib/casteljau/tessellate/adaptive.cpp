#include "casteljau/tessellate/adaptive.h"

#include "casteljau/tessellate/grid_vertices.h"
#include "casteljau/tessellate/screen_flatness.h"

#include <algorithm>
#include <unordered_map>

namespace casteljau {

namespace {

// Piece corners live on a grid of kGrid steps per patch side.
constexpr std::uint32_t kGrid = 1u << kMaxPatchDepth;

struct Leaf {
    std::uint32_t u0, u1, v0, v1;
};

// A line pieces' sides lie on, and whether its parameter runs against the patch's.
struct LineRef {
    std::uint64_t key;
    bool reversed;
};

// Where the vertices on each line are, in the line's own parameter.
class LineVertices {
  public:
    void add(LineRef l, std::uint32_t p) { lines_[l.key].push_back(l.reversed ? kGrid - p : p); }
    void finish() {
        for (auto& [key, v] : lines_) {
            std::sort(v.begin(), v.end());
            v.erase(std::unique(v.begin(), v.end()), v.end());
        }
    }
    // The parameters strictly between a and b (patch orientation), in order from a to b.
    void between(LineRef l, std::uint32_t a, std::uint32_t b,
                 std::vector<std::uint32_t>& out) const {
        out.clear();
        const auto it = lines_.find(l.key);
        if (it == lines_.end()) return;
        const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
        const std::uint32_t clo = l.reversed ? kGrid - hi : lo, chi = l.reversed ? kGrid - lo : hi;
        const auto& v = it->second;
        for (auto p = std::upper_bound(v.begin(), v.end(), clo); p != v.end() && *p < chi; ++p)
            out.push_back(l.reversed ? kGrid - *p : *p);
        if ((out.size() > 1) && ((out.front() < out.back()) != (a < b)))
            std::reverse(out.begin(), out.end());
    }

  private:
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> lines_;
};

// The lines of one patch: iso-lines inside it, shared edges on its border.
struct PatchLines {
    std::uint64_t patch;
    std::array<EdgeRef, 4> edges;

    LineRef boundary(Side s) const { return {(1ull << 63) | edges[s].id, edges[s].reversed}; }
    LineRef interior(std::uint64_t dir, std::uint32_t at) const {
        return {(patch << 18) | (dir << 17) | at, false};
    }
    // v = j, parameter u; and u = i, parameter v.
    LineRef horizontal(std::uint32_t j) const {
        return j == 0 ? boundary(kBottom) : j == kGrid ? boundary(kTop) : interior(0, j);
    }
    LineRef vertical(std::uint32_t i) const {
        return i == 0 ? boundary(kLeft) : i == kGrid ? boundary(kRight) : interior(1, i);
    }
};

template <class Patch>
struct Piece {
    Patch p;
    Leaf at;
    int depth_u, depth_v;
};

// Pass 1: split one patch into flat pieces; record their corners on their
// lines. Once `leaves` holds `budget` pieces, nothing more is split; returns
// whether a piece was emitted unchecked for that reason.
template <class Patch>
bool subdivide(const Patch& patch, const PatchLines& lines, const ScreenProjection& view,
               double tolerance, std::size_t budget, LineVertices& registry,
               std::vector<Leaf>& leaves) {
    // Each split pops one piece and pushes two, so the stack never holds more
    // than one piece per level of the deepest path, plus one.
    Piece<Patch> stack[2 * kMaxPatchDepth + 1];
    int top = 0;
    stack[top++] = {patch, {0, kGrid, 0, kGrid}, 0, 0};
    bool cut_short = false;
    while (top > 0) {
        const Piece<Patch> piece = stack[--top];
        const bool spent = leaves.size() + std::size_t(top) >= budget;
        cut_short = cut_short || spent;
        const ScreenFlatness f = spent ? ScreenFlatness{} : screen_flatness(piece.p, view);
        const bool can_u = piece.depth_u < kMaxPatchDepth, can_v = piece.depth_v < kMaxPatchDepth;
        if (spent || !f.visible || f.bound <= tolerance || (!can_u && !can_v)) {
            const Leaf& l = piece.at;
            leaves.push_back(l);
            for (const std::uint32_t i : {l.u0, l.u1})
                for (const std::uint32_t j : {l.v0, l.v1}) {
                    registry.add(lines.horizontal(j), i);
                    registry.add(lines.vertical(i), j);
                }
            continue;
        }
        // Split where the bending is; a piece that only twists, across its wider side.
        const bool bends = std::max(f.u_bend, f.v_bend) > 0.1 * tolerance;
        bool in_u = bends ? f.u_bend >= f.v_bend : f.u_width >= f.v_width;
        if (!can_u || !can_v) in_u = can_u;
        const Leaf& l = piece.at;
        if (in_u) {
            const auto halves = piece.p.split_u(0.5);
            const std::uint32_t m = (l.u0 + l.u1) / 2;
            stack[top++] = {halves[1], {m, l.u1, l.v0, l.v1}, piece.depth_u + 1, piece.depth_v};
            stack[top++] = {halves[0], {l.u0, m, l.v0, l.v1}, piece.depth_u + 1, piece.depth_v};
        } else {
            const auto halves = piece.p.split_v(0.5);
            const std::uint32_t m = (l.v0 + l.v1) / 2;
            stack[top++] = {halves[1], {l.u0, l.u1, m, l.v1}, piece.depth_u, piece.depth_v + 1};
            stack[top++] = {halves[0], {l.u0, l.u1, l.v0, m}, piece.depth_u, piece.depth_v + 1};
        }
    }
    return cut_short;
}

// Pass 2: triangulate one piece through every vertex on its sides.
template <class Patch>
class PieceTriangulator {
  public:
    PieceTriangulator(MeshAssembler& a, const Patch& patch, std::uint32_t index,
                      const PatchLines& lines, const LineVertices& registry, const Mesh& mesh)
        : a_(a), grid_(a, patch, index), lines_(lines), registry_(registry), mesh_(mesh) {}

    void triangulate(const Leaf& l) {
        ring_.clear();
        corner(l.u0, l.v0);
        side(lines_.horizontal(l.v0), l.u0, l.u1, [&](std::uint32_t i) { corner(i, l.v0); });
        corner(l.u1, l.v0);
        side(lines_.vertical(l.u1), l.v0, l.v1, [&](std::uint32_t j) { corner(l.u1, j); });
        corner(l.u1, l.v1);
        side(lines_.horizontal(l.v1), l.u1, l.u0, [&](std::uint32_t i) { corner(i, l.v1); });
        corner(l.u0, l.v1);
        side(lines_.vertical(l.u0), l.v1, l.v0, [&](std::uint32_t j) { corner(l.u0, j); });
        const std::uint32_t patch = grid_.patch_index();
        if (ring_.size() == 4) {
            const auto& p = mesh_.positions;
            const bool d02 =
                distance(p[ring_[0].v], p[ring_[2].v]) <= distance(p[ring_[1].v], p[ring_[3].v]);
            const int t[2][3] = {{0, 1, d02 ? 2 : 3}, {d02 ? 0 : 1, 2, 3}};
            for (const auto& tri : t)
                a_.triangle({ring_[tri[0]].v, ring_[tri[1]].v, ring_[tri[2]].v},
                            {patch, {ring_[tri[0]].uv, ring_[tri[1]].uv, ring_[tri[2]].uv}});
            return;
        }
        const Point c{0.5 * (l.u0 + l.u1) / kGrid, 0.5 * (l.v0 + l.v1) / kGrid};
        const std::uint32_t centre = grid_.interior(c.x, c.y);
        for (std::size_t k = 0; k < ring_.size(); ++k) {
            const Corner& p = ring_[k];
            const Corner& q = ring_[(k + 1) % ring_.size()];
            a_.triangle({centre, p.v, q.v}, {patch, {c, p.uv, q.uv}});
        }
    }

  private:
    struct Corner {
        std::uint32_t v;
        Point uv;
    };

    void corner(std::uint32_t i, std::uint32_t j) {
        ring_.push_back({grid_.at(i, kGrid, j, kGrid), {double(i) / kGrid, double(j) / kGrid}});
    }
    template <class F>
    void side(LineRef line, std::uint32_t from, std::uint32_t to, F&& f) {
        registry_.between(line, from, to, between_);
        for (const std::uint32_t p : between_) f(p);
    }

    MeshAssembler& a_;
    GridVertices<Patch> grid_;
    const PatchLines& lines_;
    const LineVertices& registry_;
    const Mesh& mesh_;
    std::vector<Corner> ring_;
    std::vector<std::uint32_t> between_;
};

} // namespace

std::size_t default_piece_budget(const ScreenProjection& view) {
    const std::size_t pixels = std::size_t(view.width) * std::size_t(view.height);
    return std::min(kMaxPieces, kMaxPiecesPerPixel * pixels);
}

AdaptiveStats tessellate_adaptive(const PatchModel& model, const ScreenProjection& view,
                                  double tolerance, Mesh& out) {
    return tessellate_adaptive(model, view, tolerance, default_piece_budget(view), out);
}

AdaptiveStats tessellate_adaptive(const PatchModel& model, const ScreenProjection& view,
                                  double tolerance, std::size_t piece_budget, Mesh& out) {
    out.clear();
    MeshAssembler assembler(out);
    LineVertices registry;
    std::vector<PatchLines> lines(model.patches.size());
    std::vector<Leaf> leaves;
    std::vector<std::size_t> first_leaf(model.patches.size() + 1, 0);
    bool reached = false;
    for (std::uint32_t index = 0; index < model.patches.size(); ++index) {
        std::visit(
            [&](const auto& patch) {
                lines[index] = {index, boundary_edges(assembler, patch)};
                // Every patch keeps at least one piece of the budget.
                const std::size_t budget = std::max(leaves.size() + 1, piece_budget);
                reached =
                    subdivide(patch, lines[index], view, tolerance, budget, registry, leaves) ||
                    reached;
            },
            model.patches[index]);
        first_leaf[index + 1] = leaves.size();
    }
    registry.finish();
    for (std::uint32_t index = 0; index < model.patches.size(); ++index) {
        std::visit(
            [&](const auto& patch) {
                PieceTriangulator t(assembler, patch, index, lines[index], registry, out);
                for (std::size_t k = first_leaf[index]; k < first_leaf[index + 1]; ++k)
                    t.triangulate(leaves[k]);
            },
            model.patches[index]);
    }
    return {leaves.size(), reached};
}

} // namespace casteljau
