#include "casteljau/paint/straight_rgba.h"

#include <cstddef>

namespace casteljau {

template <class Pixel>
void straight_rgba(const BasicCanvas<Pixel>& canvas, std::span<float> out) {
    const int w = canvas.width(), h = canvas.height();
    for (int y = 0; y < h; ++y) {
        const Pixel* src = canvas.row(y);
        float* dst = out.data() + std::size_t(y) * std::size_t(w) * 4;
        for (int x = 0; x < w; ++x, dst += 4) {
            const Rgba c = straight_of(to_premul(src[x]));
            dst[0] = c.r, dst[1] = c.g, dst[2] = c.b, dst[3] = c.a;
        }
    }
}

template <class Pixel>
void straight_rgba8(const BasicCanvas<Pixel>& canvas, std::span<std::uint8_t> out,
                    bool onto_white) {
    const int w = canvas.width(), h = canvas.height();
    for (int y = 0; y < h; ++y) {
        const Pixel* src = canvas.row(y);
        std::uint8_t* dst = out.data() + std::size_t(y) * std::size_t(w) * 4;
        for (int x = 0; x < w; ++x, dst += 4) {
            Premul p = to_premul(src[x]);
            if (onto_white) {
                const float k = 1.0f - p.a;
                p = {p.r + k, p.g + k, p.b + k, 1.0f};
            }
            const Rgba c = straight_of(p);
            dst[0] = channel_to_u8(c.r), dst[1] = channel_to_u8(c.g);
            dst[2] = channel_to_u8(c.b), dst[3] = channel_to_u8(c.a);
        }
    }
}

template void straight_rgba(const Canvas&, std::span<float>);
template void straight_rgba(const Canvas8&, std::span<float>);
template void straight_rgba8(const Canvas&, std::span<std::uint8_t>, bool);
template void straight_rgba8(const Canvas8&, std::span<std::uint8_t>, bool);

} // namespace casteljau
