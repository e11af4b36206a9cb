// pathLength (SVG 2, 9.1.4): the author's total length of a shape's path.
// Distances along the path are then in its units: a stroke's dash array
// and dash offset, and the startOffset of a textPath that references the
// shape (a percentage of it aside). The shape's length is measured along its
// outline flattened within 1e-5 of its size (path_measure.h), and each
// distance scaled by length / pathLength (shapes.h's from_path_length).
//
// pathLength="0" is a factor of infinity: a dash pattern becomes its first
// dash drawn forever, a solid stroke (a first dash of 0, the pattern's
// gaps forever, would draw nothing: taken as solid too, the rarer case
// given up for one rule), and a startOffset other than 0 moves the text off
// the path. A negative pathLength is an error: a warning, and ignored.
#include "casteljau/curve/path_measure.h"
#include "casteljau/svg/detail/reader_impl.h"
#include "casteljau/svg/shapes.h"

#include <cmath>

namespace casteljau::svg_detail {

std::optional<double> Reader::path_length(const pugi::xml_node& n) {
    const pugi::xml_attribute a = n.attribute("pathLength");
    if (!a) return std::nullopt;
    const std::optional<double> v = parse_number(a.value());
    if (!v || *v < 0) {
        problem(n, std::string("attribute pathLength: '") + a.value() +
                       "' is not a non-negative number; ignored");
        return std::nullopt;
    }
    return v;
}

double Reader::measured_length(const Path& p) {
    const Rect box = p.control_bounds();
    const double size = box.is_empty() ? 0 : std::hypot(box.width(), box.height());
    return PathMeasure(p, size > 0 ? size * 1e-5 : 1).length();
}

void Reader::dashes_in_path_length(const pugi::xml_node& n, Shape& s) {
    StrokeGeometry& g = s.stroke->geometry;
    const std::optional<double> author = path_length(n);
    if (!author) return;
    if (*author == 0) {
        g.dashes.clear(), g.dash_offset = 0; // top of the file
        return;
    }
    const double length = measured_length(s.path);
    for (double& d : g.dashes) d = from_path_length(d, length, *author);
    g.dash_offset = from_path_length(g.dash_offset, length, *author);
}

} // namespace casteljau::svg_detail
