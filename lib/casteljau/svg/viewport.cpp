#include "casteljau/svg/viewport.h"

#include "casteljau/svg/style.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace casteljau {

ViewBoxResult parse_view_box(std::string_view text) {
    std::string s(text);
    std::replace(s.begin(), s.end(), ',', ' ');
    std::istringstream words(s);
    double v[4];
    int n = 0;
    for (std::string tok; words >> tok;) {
        const auto x = parse_number(tok);
        if (!x || n == 4)
            return {{}, "viewBox: '" + std::string(text) + "' is not four numbers; ignored"};
        v[n++] = *x;
    }
    if (n != 4) return {{}, "viewBox: '" + std::string(text) + "' is not four numbers; ignored"};
    if (v[2] < 0 || v[3] < 0)
        return {{}, "viewBox: a negative width or height is an error; ignored"};
    return {ViewBox{v[0], v[1], v[2], v[3]}, {}};
}

std::optional<AspectRatio> parse_aspect_ratio(std::string_view text) {
    std::istringstream words{std::string(text)};
    std::string w;
    if (!(words >> w)) return std::nullopt;
    if (w == "defer" && !(words >> w)) return std::nullopt;
    AspectRatio ar;
    const auto axis = [](std::string_view a) -> std::optional<AspectRatio::Align> {
        if (a == "Min") return AspectRatio::Align::Min;
        if (a == "Mid") return AspectRatio::Align::Mid;
        if (a == "Max") return AspectRatio::Align::Max;
        return std::nullopt;
    };
    if (w == "none") {
        ar.none = true;
    } else {
        // x{Min,Mid,Max}Y{Min,Mid,Max}
        if (w.size() != 8 || w[0] != 'x' || w[4] != 'Y') return std::nullopt;
        const auto x = axis(std::string_view(w).substr(1, 3));
        const auto y = axis(std::string_view(w).substr(5, 3));
        if (!x || !y) return std::nullopt;
        ar.x = *x, ar.y = *y;
    }
    if (words >> w) {
        if (w != "meet" && w != "slice") return std::nullopt;
        ar.slice = w == "slice";
    }
    if (words >> w) return std::nullopt;
    return ar;
}

Affine view_box_transform(const ViewBox& box, const AspectRatio& ar, double vx, double vy,
                          double width, double height) {
    double sx = width / box.w, sy = height / box.h;
    if (ar.none)
        return Affine::translate({vx, vy}) * Affine::scale(sx, sy) *
               Affine::translate({-box.x, -box.y});
    sx = sy = ar.slice ? std::max(sx, sy) : std::min(sx, sy);
    const auto offset = [](AspectRatio::Align a, double avail, double used) {
        return a == AspectRatio::Align::Min   ? 0.0
               : a == AspectRatio::Align::Mid ? (avail - used) / 2
                                              : avail - used;
    };
    const double tx = vx + offset(ar.x, width, box.w * sx),
                 ty = vy + offset(ar.y, height, box.h * sy);
    return Affine::translate({tx, ty}) * Affine::scale(sx) * Affine::translate({-box.x, -box.y});
}

} // namespace casteljau
