// Fuzz target: whatever the SVG reader accepts is rendered, scaled down to
// fit 96 x 96 px so that every input costs about the same, through the same
// banded renderer as the CLI.
#include "casteljau/render/bands.h"
#include "casteljau/svg/reader.h"
#include "fuzz_target.h"

#include <algorithm>
#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace casteljau;
    const SvgResult r = parse_svg({reinterpret_cast<const char*>(data), size}, "fuzz.svg");
    if (!r.scene) return 0;
    const Scene& scene = *r.scene;
    constexpr double kSide = 96;
    const double s = std::min(1.0, kSide / std::max(scene.width, scene.height));
    const int w = std::max(1, int(std::ceil(scene.width * s))),
              h = std::max(1, int(std::ceil(scene.height * s)));
    static BandRenderer renderer; // reused, as the CLI reuses it across inputs
    Canvas canvas;
    canvas.reset(w, h);
    renderer.render(scene, Affine::scale(s), canvas, RenderOptions{}, Premul{}, 1);
    return 0;
}
