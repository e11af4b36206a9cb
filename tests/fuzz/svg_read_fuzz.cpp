// Fuzz target: the SVG reader (svg/reader.h) on arbitrary bytes. It must
// return a scene or a located error ("fuzz.svg:LINE: ..."), never both.
#include "casteljau/svg/reader.h"
#include "fuzz_target.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const casteljau::SvgResult r =
        casteljau::parse_svg({reinterpret_cast<const char*>(data), size}, "fuzz.svg");
    if (r.scene.has_value() == !r.error.empty()) std::abort();
    if (!r.scene && r.error.rfind("fuzz.svg:", 0) != 0) std::abort();
    return 0;
}
