// Fuzz target: SVG path data (curve/path_data.h). Whatever the parser
// accepts must be finite (overflowing numbers and relative coordinates that
// add up past the double range are errors, never infinities in the path),
// and the error offset must lie inside the input.
#include "casteljau/curve/path_data.h"
#include "fuzz_target.h"

#include <cmath>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace casteljau;
    const PathDataResult r = parse_path_data({reinterpret_cast<const char*>(data), size});
    if (r.error && r.error->offset > size) std::abort();
    if (r.path.empty()) return 0;
    const Rect hull = r.path.control_bounds();
    const Rect tight = r.path.bounds();
    for (const double v :
         {hull.x0, hull.y0, hull.x1, hull.y1, tight.x0, tight.y0, tight.x1, tight.y1})
        if (!std::isfinite(v)) std::abort();
    return 0;
}
