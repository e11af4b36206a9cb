// Bidi levels with FriBidi (see bidi.h). FriBidi implements UAX #9 up to
// rule L1; the visual order of runs (L2) is the classic reversal: from the
// highest level down to the lowest odd one, every maximal sequence of runs
// at that level or above is reversed.
#include "casteljau/text/bidi.h"

#include "casteljau/text/detail/text_libs.h"

#include <algorithm>

namespace casteljau {

std::vector<std::uint8_t> bidi_levels(std::u32string_view text, bool rtl) {
    const auto n = FriBidiStrIndex(text.size());
    std::vector<std::uint8_t> levels(text.size(), rtl ? 1 : 0);
    if (n == 0 || !text_libs().loaded()) return levels;
    std::vector<FriBidiCharType> types(text.size());
    std::vector<FriBidiBracketType> brackets(text.size());
    std::vector<FriBidiLevel> out(text.size());
    const auto* chars = reinterpret_cast<const FriBidiChar*>(text.data());
    text_libs().fribidi_get_bidi_types(chars, n, types.data());
    text_libs().fribidi_get_bracket_types(chars, n, types.data(), brackets.data());
    FriBidiParType base = rtl ? FRIBIDI_PAR_RTL : FRIBIDI_PAR_LTR;
    if (text_libs().fribidi_get_par_embedding_levels_ex(types.data(), brackets.data(), n, &base,
                                                        out.data()) == 0)
        return levels; // out of memory in FriBidi: the base level
    std::copy(out.begin(), out.end(), levels.begin());
    return levels;
}

std::vector<BidiRun> visual_runs(const std::vector<std::uint8_t>& levels) {
    std::vector<BidiRun> runs;
    for (std::size_t i = 0; i < levels.size();) {
        std::size_t j = i + 1;
        while (j < levels.size() && levels[j] == levels[i]) ++j;
        runs.push_back({i, j, levels[i]});
        i = j;
    }
    if (runs.empty()) return runs;
    std::uint8_t highest = 0, lowest_odd = 255;
    for (const BidiRun& r : runs) {
        highest = std::max(highest, r.level);
        if (r.level & 1) lowest_odd = std::min(lowest_odd, r.level);
    }
    for (int level = highest; level >= lowest_odd && level > 0; --level)
        for (std::size_t i = 0; i < runs.size();) {
            if (runs[i].level < level) {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j < runs.size() && runs[j].level >= level) ++j;
            std::reverse(runs.begin() + std::ptrdiff_t(i), runs.begin() + std::ptrdiff_t(j));
            i = j;
        }
    return runs;
}

} // namespace casteljau
