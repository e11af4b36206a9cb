// What several fuzz targets share: reading values from the fuzzer's bytes,
// and drawing a read scene the way the CLI does, scaled down so that every
// input costs about the same.
#pragma once

#include "casteljau/render/bands.h"
#include "casteljau/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace casteljau::fuzz {

/// Reads values from the input, 0 once it runs out.
struct Bytes {
    const std::uint8_t* p;
    std::size_t n;
    /// Also tiny and NaN numbers: for targets that read them through a
    /// parser (which must reject them), not for the core, which assumes
    /// finite input.
    bool tiny_and_nan = false;
    std::uint8_t byte() { return n ? (--n, *p++) : 0; }
    /// A double in a range that reaches hostile values: +-1e-3 .. 1e6, and
    /// now and then a huge one (or a tiny or NaN one, see above).
    double number() {
        const std::uint8_t k = byte();
        if (k == 255) return 1e300;
        if (k == 254) return -1e300;
        if (tiny_and_nan && k == 253) return 1e-300;
        if (tiny_and_nan && k == 252) return std::nan("");
        return (byte() - 128) * std::pow(10.0, (k % 10) - 3) / 16;
    }
    /// One of a list.
    template <std::size_t N>
    const char* pick(const char* const (&list)[N]) {
        return list[byte() % N];
    }
};

/// Renders `scene` fitted into 96 x 96 px through the banded renderer the
/// CLI uses (reused across inputs, as the CLI reuses it across files).
inline void render_small(const Scene& scene) {
    constexpr double kSide = 96;
    const double s = std::min(1.0, kSide / std::max(scene.width, scene.height));
    const int w = std::max(1, int(std::ceil(scene.width * s))),
              h = std::max(1, int(std::ceil(scene.height * s)));
    static BandRenderer renderer;
    Canvas canvas;
    canvas.reset(w, h);
    renderer.render(scene, Affine::scale(s), canvas, RenderOptions{}, Premul{}, 1);
}

} // namespace casteljau::fuzz
