// The canvas-to-bytes conversion (paint/straight_rgba.h): straight_row8's
// four-channels-at-once path gives, bit for bit, what straight_of and
// channel_to_u8 give one channel at a time, for every kind of value a
// canvas can hold (NaN, infinities, negatives and values above 1 included).
#include "casteljau/paint/straight_rgba.h"
#include "corpus.h"

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

namespace casteljau {
namespace {

/// The reference: straight_of, then channel_to_u8 of each channel.
std::array<std::uint8_t, 4> reference(const Premul& p, bool onto_white) {
    Premul q = p;
    if (onto_white) {
        const float k = 1.0f - q.a;
        q = {q.r + k, q.g + k, q.b + k, 1.0f};
    }
    const Rgba c = straight_of(q);
    return {channel_to_u8(c.r), channel_to_u8(c.g), channel_to_u8(c.b), channel_to_u8(c.a)};
}

template <class Pixel>
void expect_reference(const std::vector<Pixel>& row, const char* what) {
    for (const bool onto_white : {false, true}) {
        std::vector<std::uint8_t> out(row.size() * 4);
        straight_row8(row.data(), int(row.size()), out.data(), onto_white);
        int bad = 0;
        for (std::size_t i = 0; i < row.size(); ++i) {
            const Premul p = to_premul(row[i]);
            const auto want = reference(p, onto_white);
            for (std::size_t c = 0; c < 4; ++c)
                if (out[4 * i + c] != want[c] && bad++ < 8)
                    ADD_FAILURE() << what << " pixel (" << p.r << ", " << p.g << ", " << p.b << ", "
                                  << p.a << ") onto_white " << onto_white << " channel " << c
                                  << ": " << int(out[4 * i + c]) << ", want " << int(want[c]);
        }
        EXPECT_EQ(bad, 0) << what;
    }
}

TEST(StraightRgba, RowOfFloatPixelsMatchesTheScalarReference) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float specials[] = {0.0f,   -0.0f,   1.0f, 0.5f, 1.0f / 255, 0.5f / 255, 1e-30f,
                              -1e-3f, 1.0001f, 7.0f, nan,  inf,        -inf};
    std::vector<Premul> row;
    for (float a : specials)
        for (float c : specials) row.push_back({c, 0.5f * c, a * c, a});
    // Every channel value halfway between two bytes, at alpha 1 (rounding's edge).
    for (int k = 0; k < 255; ++k) {
        const float v = (float(k) + 0.5f) / 255.0f;
        row.push_back({v, std::nextafter(v, 0.0f), std::nextafter(v, 1.0f), 1.0f});
    }
    testing::Rng rng(2503);
    for (int i = 0; i < 100000; ++i) {
        const float a = rng.integer(0, 3) == 0 ? 1.0f : float(rng.uniform(0, 1));
        row.push_back({a * float(rng.uniform(0, 1)), a * float(rng.uniform(0, 1)),
                       a * float(rng.uniform(0, 1.01)), a});
    }
    expect_reference(row, "float");
}

// Every pair of a color byte and an alpha byte, premultiplied bytes as a
// Canvas8 holds them.
TEST(StraightRgba, RowOfEveryBytePixelMatchesTheScalarReference) {
    std::vector<Premul8> row;
    for (int a = 0; a < 256; ++a)
        for (int c = 0; c < 256; ++c)
            row.push_back(
                {std::uint8_t(c), std::uint8_t(255 - c), std::uint8_t(c / 2), std::uint8_t(a)});
    expect_reference(row, "bytes");
}

} // namespace
} // namespace casteljau
