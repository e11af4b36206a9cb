#include "casteljau/io/detail/png_filter.h"

#include <algorithm>
#include <cstdlib>

namespace casteljau::detail {

namespace {

/// PNG 9.4: the one of a, b, c nearest to a + b - c, ties going to a, then b.
inline int paeth(int a, int b, int c) {
    const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/// A filtered byte's cost: its magnitude read as signed.
inline int cost(int residual) { return std::abs(int(std::int8_t(std::uint8_t(residual)))); }

/// Byte i of `row` filtered with `type`, for any i (the first pixel's left
/// neighbours are 0).
inline std::uint8_t filtered(int type, const std::uint8_t* row, const std::uint8_t* prior,
                             std::size_t i, std::size_t bpp) {
    const int x = row[i], b = prior[i];
    const int a = i >= bpp ? row[i - bpp] : 0, c = i >= bpp ? prior[i - bpp] : 0;
    switch (type) {
    case 1:
        return std::uint8_t(x - a);
    case 2:
        return std::uint8_t(x - b);
    case 3:
        return std::uint8_t(x - (a + b) / 2);
    case 4:
        return std::uint8_t(x - paeth(a, b, c));
    default:
        return std::uint8_t(x);
    }
}

// add_costs sums in int, which lets GCC vectorize its loop; a call gets at
// most kCostBlock bytes, whose costs (128 at most each) sum below 2^31.
constexpr std::size_t kCostBlock = std::size_t(1) << 20;

/// Adds the five types' costs of bytes [from, to) of `row` (from >= bpp:
/// every byte has its left neighbours) to `sums`.
void add_costs(const std::uint8_t* row, const std::uint8_t* prior, std::size_t from, std::size_t to,
               std::size_t bpp, long* sums) {
    int none = 0, sub = 0, up = 0, average = 0, pae = 0;
    for (std::size_t i = from; i < to; ++i) {
        const int x = row[i], a = row[i - bpp], b = prior[i], c = prior[i - bpp];
        none += cost(x), sub += cost(x - a), up += cost(x - b);
        average += cost(x - (a + b) / 2), pae += cost(x - paeth(a, b, c));
    }
    sums[0] += none, sums[1] += sub, sums[2] += up, sums[3] += average, sums[4] += pae;
}

} // namespace

int best_png_filter(const std::uint8_t* row, const std::uint8_t* prior, std::size_t n,
                    std::size_t bpp) {
    long sums[kPngFilterTypes] = {};
    // The first pixel apart, so that the main loop has no branch on the position.
    for (std::size_t i = 0; i < std::min(bpp, n); ++i)
        for (int t = 0; t < kPngFilterTypes; ++t) sums[t] += cost(filtered(t, row, prior, i, bpp));
    for (std::size_t i = bpp; i < n; i += kCostBlock)
        add_costs(row, prior, i, std::min(n, i + kCostBlock), bpp, sums);
    return int(std::min_element(sums, sums + kPngFilterTypes) - sums);
}

void png_filter_row(int type, const std::uint8_t* row, const std::uint8_t* prior, std::size_t n,
                    std::size_t bpp, std::uint8_t* out) {
    // The first pixel apart, and the switch outside the loops: each loop is
    // one straight pass.
    const std::size_t head = std::min(bpp, n);
    for (std::size_t i = 0; i < head; ++i) out[i] = filtered(type, row, prior, i, bpp);
    switch (type) {
    case 1:
        for (std::size_t i = head; i < n; ++i) out[i] = std::uint8_t(row[i] - row[i - bpp]);
        break;
    case 2:
        for (std::size_t i = head; i < n; ++i) out[i] = std::uint8_t(row[i] - prior[i]);
        break;
    case 3:
        for (std::size_t i = head; i < n; ++i)
            out[i] = std::uint8_t(row[i] - (row[i - bpp] + prior[i]) / 2);
        break;
    case 4:
        for (std::size_t i = head; i < n; ++i)
            out[i] = std::uint8_t(row[i] - paeth(row[i - bpp], prior[i], prior[i - bpp]));
        break;
    default:
        std::copy(row + head, row + n, out + head);
    }
}

} // namespace casteljau::detail
