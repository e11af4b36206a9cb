// The Unicode the text library stands on: the bidi levels of UAX #9 and
// their visual order (text/bidi.h, rule L2), and UTF-8 decoding
// (text/utf8.h) with U+FFFD for each maximal subpart of an ill-formed
// sequence (Unicode 15, 3.9).
#include "casteljau/text/bidi.h"
#include "casteljau/text/utf8.h"
#include "corpus.h"
#include "text_test_support.h"

#include <algorithm>
#include <cstdint>
#include <gtest/gtest.h>
#include <ostream>
#include <string>
#include <vector>

namespace casteljau::text_test {
namespace {

// ------------------------------------------------------------------- bidi

std::vector<std::uint8_t> levels_of(const std::string& utf8, bool rtl) {
    return bidi_levels(decode_utf8(utf8), rtl);
}

using Levels = std::vector<std::uint8_t>;

struct LevelRun {
    std::size_t begin, end;
    int level;
    bool operator==(const LevelRun&) const = default;
};
std::ostream& operator<<(std::ostream& os, const LevelRun& r) {
    return os << "[" << r.begin << ", " << r.end << ") at " << r.level;
}
std::vector<LevelRun> runs_of(const Levels& levels) {
    std::vector<LevelRun> out;
    for (const BidiRun& r : visual_runs(levels)) out.push_back({r.begin, r.end, r.level});
    return out;
}

TEST(Bidi, LevelsOfSmallParagraphs) {
    EXPECT_EQ(levels_of("abc", false), (Levels{0, 0, 0}));
    EXPECT_EQ(runs_of(levels_of("abc", false)), (std::vector<LevelRun>{{0, 3, 0}}));
    // Left to right in a right-to-left paragraph rises to level 2.
    EXPECT_EQ(levels_of("abc", true), (Levels{2, 2, 2}));
    const std::string mixed = std::string("abc ") + kAlefBetGimel;
    EXPECT_EQ(levels_of(mixed, false), (Levels{0, 0, 0, 0, 1, 1, 1}));
    EXPECT_EQ(runs_of(levels_of(mixed, false)), (std::vector<LevelRun>{{0, 4, 0}, {4, 7, 1}}));
    // Base right to left: the space between the two takes the paragraph's
    // direction, and the Latin word is drawn to the right of the Hebrew.
    EXPECT_EQ(levels_of(mixed, true), (Levels{2, 2, 2, 1, 1, 1, 1}));
    EXPECT_EQ(runs_of(levels_of(mixed, true)), (std::vector<LevelRun>{{3, 7, 1}, {0, 3, 2}}));
    // European digits after Hebrew in a left-to-right paragraph: level 2,
    // drawn left to right, left of the Hebrew.
    const std::string digits = std::string(kAlefBetGimel) + " 123";
    EXPECT_EQ(levels_of(digits, false), (Levels{1, 1, 1, 1, 2, 2, 2}));
    EXPECT_EQ(runs_of(levels_of(digits, false)), (std::vector<LevelRun>{{4, 7, 2}, {0, 4, 1}}));
    EXPECT_TRUE(bidi_levels(U"", true).empty());
    EXPECT_TRUE(visual_runs({}).empty());
}

// L2 on levels set by hand (an override, say): from the highest level down
// to the lowest odd one, every sequence at that level or above reverses.
TEST(Bidi, VisualRunsReverseFromTheHighestLevel) {
    EXPECT_EQ(runs_of({0, 1, 1, 2, 2, 1, 0}),
              (std::vector<LevelRun>{{0, 1, 0}, {5, 6, 1}, {3, 5, 2}, {1, 3, 1}, {6, 7, 0}}));
    // 3: c alone; 2: b c -> c b; 1: a c b -> b c a.
    EXPECT_EQ(runs_of({1, 2, 3}), (std::vector<LevelRun>{{1, 2, 2}, {2, 3, 3}, {0, 1, 1}}));
    // Even levels alone reverse in pairs: the order stays.
    EXPECT_EQ(runs_of({0, 2, 4, 2}),
              (std::vector<LevelRun>{{0, 1, 0}, {1, 2, 2}, {2, 3, 4}, {3, 4, 2}}));
    // Against a brute-force L2 on characters, over seeded random levels.
    testing::Rng rng(7);
    for (int t = 0; t < 500; ++t) {
        Levels levels(std::size_t(rng.integer(1, 12)));
        for (auto& l : levels) l = std::uint8_t(rng.integer(0, 4));
        std::vector<std::size_t> order(levels.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        const int highest = *std::max_element(levels.begin(), levels.end());
        const int lowest = *std::min_element(levels.begin(), levels.end());
        for (int level = highest; level >= (lowest | 1); --level)
            for (std::size_t i = 0; i < order.size();) {
                if (levels[order[i]] < level) {
                    ++i;
                    continue;
                }
                std::size_t j = i;
                while (j < order.size() && levels[order[j]] >= level) ++j;
                std::reverse(order.begin() + std::ptrdiff_t(i), order.begin() + std::ptrdiff_t(j));
                i = j;
            }
        // The runs, each read in its own direction, give that order.
        std::vector<std::size_t> from_runs;
        for (const BidiRun& r : visual_runs(levels))
            for (std::size_t k = 0; k < r.end - r.begin; ++k)
                from_runs.push_back(r.rtl() ? r.end - 1 - k : r.begin + k);
        EXPECT_EQ(from_runs, order) << "case " << t;
    }
}

// ------------------------------------------------------------------ UTF-8

std::u32string fffd(int n) { return std::u32string(std::size_t(n), U'\uFFFD'); }

TEST(Utf8, WellFormedSequences) {
    EXPECT_EQ(decode_utf8(""), U"");
    EXPECT_EQ(decode_utf8("Az~\x7F"), U"Az~\x7F");
    EXPECT_EQ(decode_utf8(std::string("a\0b", 3)), std::u32string(U"a\0b", 3));
    EXPECT_EQ(decode_utf8("\xC2\x80\xC3\xA9\xDF\xBF"), U"\u0080\u00E9\u07FF");
    EXPECT_EQ(decode_utf8("\xE0\xA0\x80\xE2\x82\xAC\xED\x9F\xBF\xEE\x80\x80\xEF\xBF\xBF"),
              U"\u0800\u20AC\uD7FF\uE000\uFFFF");
    EXPECT_EQ(decode_utf8("\xF0\x90\x80\x80\xF0\x9F\x98\x80\xF4\x8F\xBF\xBF"),
              U"\U00010000\U0001F600\U0010FFFF");
}

// Each maximal subpart of an ill-formed sequence is one U+FFFD (Unicode 15,
// 3.9, "U+FFFD substitution of maximal subparts").
TEST(Utf8, IllFormedSequencesBecomeOneReplacementPerMaximalSubpart) {
    // Overlong forms: C0 and C1 never start a sequence; E0 80..9F and
    // F0 80..8F are not the start of one.
    EXPECT_EQ(decode_utf8("\xC0\x80"), fffd(2));
    EXPECT_EQ(decode_utf8("\xC1\xBF"), fffd(2));
    EXPECT_EQ(decode_utf8("\xE0\x9F\xBF"), fffd(3));
    EXPECT_EQ(decode_utf8("\xF0\x8F\xBF\xBF"), fffd(4));
    // Surrogates, ED A0..BF.
    EXPECT_EQ(decode_utf8("\xED\xA0\x80"), fffd(3));
    EXPECT_EQ(decode_utf8("\xED\xBF\xBF"), fffd(3));
    // Past U+10FFFF: F4 90.., and F5..FF never start one.
    EXPECT_EQ(decode_utf8("\xF4\x90\x80\x80"), fffd(4));
    EXPECT_EQ(decode_utf8("\xF5\x80\x80\x80"), fffd(4));
    EXPECT_EQ(decode_utf8("\xFF\xFE"), fffd(2));
    // Lone continuation bytes.
    EXPECT_EQ(decode_utf8("\x80\xBF"), fffd(2));
    // Truncated: a well-begun sequence cut short is one subpart.
    EXPECT_EQ(decode_utf8("\xE2\x82"), fffd(1));
    EXPECT_EQ(decode_utf8("\xE2\x82"
                          "A"),
              U"\uFFFDA");
    EXPECT_EQ(decode_utf8("\xF0\x9F\x98"), fffd(1));
    EXPECT_EQ(decode_utf8("\xF0\x9F\x98\xE2\x82\xAC"), U"\uFFFD\u20AC");
    EXPECT_EQ(decode_utf8("\xC3"), fffd(1));
    // The standard's examples (table 3-8 and the text before it).
    EXPECT_EQ(decode_utf8("\xF1\x80\x80\xE1\x80\xC2\x41"), U"\uFFFD\uFFFD\uFFFDA");
    EXPECT_EQ(decode_utf8("\x61\xF1\x80\x80\xE1\x80\xC2\x62\x80\x63\x80\xBF\x64"),
              U"a\uFFFD\uFFFD\uFFFDb\uFFFDc\uFFFD\uFFFDd");
}

// The library's encoder: the round trip below tests it and the decoder together.
std::string encode_utf8(char32_t c) {
    std::string s;
    append_utf8(s, c);
    return s;
}

// Every scalar value survives a round trip, and random bytes decode to
// scalar values only, never more of them than there are bytes, with the
// well-formed stretches intact.
TEST(Utf8, RoundTripsAndRandomBytes) {
    testing::Rng rng(36);
    for (int t = 0; t < 200; ++t) {
        std::u32string text;
        std::string utf8;
        for (int i = 0; i < 20; ++i) {
            const int width = rng.integer(0, 3);
            const char32_t limit[] = {0x80, 0x800, 0x10000, 0x110000};
            char32_t c = char32_t(
                rng.integer(width == 0 ? 0 : int(limit[width - 1]), int(limit[width]) - 1));
            if (c >= 0xD800 && c < 0xE000) c = 0xFFFD;
            text += c;
            utf8 += encode_utf8(c);
        }
        EXPECT_EQ(decode_utf8(utf8), text) << t;
    }
    for (int t = 0; t < 500; ++t) {
        std::string bytes;
        for (int i = rng.integer(0, 30); i > 0; --i) bytes += char(rng.integer(0, 255));
        const std::u32string out = decode_utf8(bytes);
        EXPECT_LE(out.size(), bytes.size());
        for (const char32_t c : out) {
            EXPECT_LE(c, 0x10FFFFu);
            EXPECT_FALSE(c >= 0xD800 && c < 0xE000);
        }
        // A valid character after the garbage comes through whole.
        EXPECT_EQ(decode_utf8(bytes + "\xE2\x82\xAC").back(), U'\u20AC') << t;
    }
}

} // namespace
} // namespace casteljau::text_test
