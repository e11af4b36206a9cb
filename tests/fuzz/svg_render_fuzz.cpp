// Fuzz target: whatever the SVG reader accepts is rendered, scaled down to
// fit 96 x 96 px so that every input costs about the same, through the same
// banded renderer as the CLI.
#include "casteljau/svg/reader.h"
#include "fuzz_input.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const casteljau::SvgResult r =
        casteljau::parse_svg({reinterpret_cast<const char*>(data), size}, "fuzz.svg");
    if (r.scene) casteljau::fuzz::render_small(*r.scene);
    return 0;
}
