// The Unicode bidirectional algorithm (UAX #9), with FriBidi: the embedding
// level of each character of a paragraph (even: left to right, odd: right
// to left), and the visual order of runs of equal level.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace casteljau {

/// Levels of each character; `rtl` sets the paragraph's base direction
/// (SVG's direction property). A caller that overrides the algorithm for a
/// range (unicode-bidi: bidi-override) sets those levels itself.
std::vector<std::uint8_t> bidi_levels(std::u32string_view text, bool rtl);

/// A maximal range of characters of one level.
struct BidiRun {
    std::size_t begin = 0, end = 0;
    std::uint8_t level = 0;
    bool rtl() const { return level & 1; } ///< an odd level: right to left
};

/// The runs of `levels` in visual order, left to right (UAX #9, L2).
std::vector<BidiRun> visual_runs(const std::vector<std::uint8_t>& levels);

} // namespace casteljau
