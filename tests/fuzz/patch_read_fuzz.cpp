// Fuzz target: the three patch readers (io/patch_read.h). The first byte
// picks the format (.bpt, .map, .json), the rest is the file. A reader must
// return a model or a located error ("fuzz:LINE: ..."), and every control
// point of a model must be finite.
#include "casteljau/io/patch_read.h"
#include "fuzz_target.h"

#include <cmath>
#include <cstdlib>
#include <variant>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace casteljau;
    if (size == 0) return 0;
    const auto format = PatchFormat(data[0] % 3);
    const PatchFile f =
        parse_patches({reinterpret_cast<const char*>(data + 1), size - 1}, format, "fuzz");
    if (f.model.has_value() == !f.error.empty()) std::abort();
    if (!f.model) {
        if (f.error.rfind("fuzz:", 0) != 0) std::abort();
        return 0;
    }
    if (f.model->patches.empty()) return 0;
    const Box3 b = f.model->control_bounds();
    for (const double v : {b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z})
        if (!std::isfinite(v)) std::abort();
    return 0;
}
