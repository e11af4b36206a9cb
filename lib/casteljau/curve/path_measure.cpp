// Arc length along a flattened path (see path_measure.h).
#include "casteljau/curve/path_measure.h"

#include "casteljau/flatten/path_flatten.h"

#include <algorithm>

namespace casteljau {

PathMeasure::PathMeasure(const Path& path, double tolerance) {
    std::vector<Polyline> lines;
    flatten_path(path, Affine::identity(), {tolerance, FlattenMethod::Guided, 0}, lines);
    closed_ = lines.size() == 1 && lines[0].closed;
    for (const Polyline& pl : lines)
        for (std::size_t i = 0; i < pl.points.size(); ++i) {
            if (i > 0) total_ += (pl.points[i] - pl.points[i - 1]).length();
            vertices_.push_back({pl.points[i], total_, i == 0});
        }
}

std::optional<PathMeasure::Place> PathMeasure::at(double distance) const {
    if (vertices_.size() < 2 || !(distance >= 0 && distance <= total_)) return std::nullopt;
    // The first edge that reaches `distance`, skipping the jumps between subpaths.
    auto it = std::lower_bound(vertices_.begin() + 1, vertices_.end(), distance,
                               [](const Vertex& v, double d) { return v.distance < d; });
    if (it == vertices_.end()) it = vertices_.end() - 1;
    while (it + 1 != vertices_.end() && (it->starts_subpath || it->distance == (it - 1)->distance))
        ++it;
    const Vertex& a = *(it - 1);
    const Vertex& b = *it;
    const Vec2 edge = b.p - a.p;
    const double len = b.distance - a.distance;
    if (len <= 0 || b.starts_subpath) return std::nullopt;
    const double t = std::clamp((distance - a.distance) / len, 0.0, 1.0);
    return Place{a.p + edge * t, edge / len};
}

} // namespace casteljau
