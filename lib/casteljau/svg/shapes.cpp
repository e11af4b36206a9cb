#include "casteljau/svg/shapes.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

namespace casteljau {

Path rect_path(double x, double y, double w, double h, double rx, double ry) {
    if (rx < 0 && ry < 0)
        rx = ry = 0;
    else if (rx < 0)
        rx = ry;
    else if (ry < 0)
        ry = rx;
    rx = std::min(rx, w / 2);
    ry = std::min(ry, h / 2);
    Path p;
    if (rx == 0 || ry == 0) {
        p.move_to({x, y});
        p.line_to({x + w, y});
        p.line_to({x + w, y + h});
        p.line_to({x, y + h});
        p.close();
        return p;
    }
    const Vec2 r{rx, ry};
    p.move_to({x + rx, y});
    p.line_to({x + w - rx, y});
    p.arc_to(r, 0, false, true, {x + w, y + ry});
    p.line_to({x + w, y + h - ry});
    p.arc_to(r, 0, false, true, {x + w - rx, y + h});
    p.line_to({x + rx, y + h});
    p.arc_to(r, 0, false, true, {x, y + h - ry});
    p.line_to({x, y + ry});
    p.arc_to(r, 0, false, true, {x + rx, y});
    p.close();
    return p;
}

Path ellipse_path(double cx, double cy, double rx, double ry) {
    Path p;
    const Vec2 r{rx, ry};
    p.move_to({cx + rx, cy});
    p.arc_to(r, 0, false, true, {cx, cy + ry});
    p.arc_to(r, 0, false, true, {cx - rx, cy});
    p.arc_to(r, 0, false, true, {cx, cy - ry});
    p.arc_to(r, 0, false, true, {cx + rx, cy});
    p.close();
    return p;
}

Path line_path(Point a, Point b) {
    Path p;
    p.move_to(a);
    p.line_to(b);
    return p;
}

Path poly_path(const std::vector<Point>& points, bool close) {
    Path p;
    if (points.size() < 2) return p;
    p.move_to(points[0]);
    for (std::size_t i = 1; i < points.size(); ++i) p.line_to(points[i]);
    if (close) p.close();
    return p;
}

PointList parse_point_list(std::string_view s) {
    PointList out;
    std::vector<double> values;
    std::size_t i = 0;
    const auto sep = [](char c) { return std::isspace(static_cast<unsigned char>(c)) || c == ','; };
    while (true) {
        while (i < s.size() && sep(s[i])) ++i;
        if (i == s.size()) break;
        const std::size_t start = i + (s[i] == '+' ? 1 : 0);
        double v;
        const auto [end, ec] = std::from_chars(s.data() + start, s.data() + s.size(), v);
        if (ec != std::errc() || !std::isfinite(v)) {
            out.error = "points: '" + std::string(s.substr(i, 16)) + "' at offset " +
                        std::to_string(i) + " is not a finite number";
            break;
        }
        values.push_back(v);
        i = std::size_t(end - s.data());
    }
    if (out.error.empty() && values.size() % 2 == 1)
        out.error = "points: odd number of coordinates (" + std::to_string(values.size()) + ")";
    for (std::size_t k = 0; k + 1 < values.size(); k += 2)
        out.points.push_back({values[k], values[k + 1]});
    return out;
}

double from_path_length(double d, double length, double path_length) {
    if (path_length > 0) return d * (length / path_length);
    return d == 0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), d);
}

} // namespace casteljau
