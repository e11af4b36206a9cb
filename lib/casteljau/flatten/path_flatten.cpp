#include "casteljau/flatten/path_flatten.h"

#include "casteljau/flatten/error.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

namespace {

int depth_of_step(double step) {
    if (!(step > 0.0)) return 0;
    int exp;
    const double m = std::frexp(step, &exp); // step = m 2^exp, m in [0.5, 1)
    return m == 0.5 ? 1 - exp : -exp;        // ceil(log2(1 / step))
}

} // namespace

FlattenStats flatten_path(const Path& path, const Affine& to_device, const FlattenOptions& options,
                          std::vector<Polyline>& out, bool measure_error) {
    FlattenStats stats;
    std::vector<FlatVertex> scratch;
    for (const Subpath& sub : path.subpaths()) {
        Polyline& line = out.emplace_back();
        line.closed = sub.closed;
        line.points.push_back(to_device * sub.start);
        for (const Segment& seg : sub.segments) {
            ++stats.curves_in;
            std::visit(
                [&](const auto& curve) {
                    const auto dev = curve.transformed(to_device);
                    scratch.clear();
                    double last_t = 0;
                    flatten_curve(dev, options, [&](const FlatVertex& v) {
                        stats.max_depth = std::max(stats.max_depth, depth_of_step(v.t - last_t));
                        last_t = v.t;
                        line.points.push_back(v.p);
                        if (measure_error) scratch.push_back(v);
                    });
                    if (measure_error)
                        stats.max_error =
                            std::max(stats.max_error, polyline_error(dev, dev.start(), scratch));
                },
                seg);
        }
        stats.segments_out += line.points.size() - 1;
    }
    return stats;
}

} // namespace casteljau
