#include "casteljau/io/png_write.h"

#include "casteljau/io/atomic_file.h"
#include "casteljau/io/detail/png_filter.h"

#include <algorithm>
#include <libdeflate.h>
#include <memory>
#include <new>
#include <string_view>
#include <utility>

namespace casteljau {

namespace {

void put_u32(std::uint8_t* p, std::uint32_t v) {
    p[0] = std::uint8_t(v >> 24), p[1] = std::uint8_t(v >> 16);
    p[2] = std::uint8_t(v >> 8), p[3] = std::uint8_t(v);
}

/// Appends a chunk (PNG 5.3): data length, type, data, CRC-32 of type and data.
void put_chunk(std::vector<std::uint8_t>& out, std::string_view type,
               std::span<const std::uint8_t> data) {
    const std::size_t at = out.size();
    out.resize(at + 12 + data.size());
    std::uint8_t* p = out.data() + at;
    put_u32(p, std::uint32_t(data.size()));
    std::copy(type.begin(), type.end(), p + 4);
    std::copy(data.begin(), data.end(), p + 8);
    put_u32(p + 8 + data.size(), libdeflate_crc32(0, p + 4, 4 + data.size()));
}

/// The rows in the file's layout: each a filter-type byte, then width * bpp
/// bytes; bpp 4 (RGBA) or 3 (RGB).
struct Layout {
    std::uint8_t* bytes = nullptr;
    std::size_t width = 0, height = 0, bpp = 4;
    std::size_t row_bytes() const { return width * bpp; }
    std::uint8_t* row(std::size_t y) const { return bytes + y * (row_bytes() + 1) + 1; }
};

bool opaque(const Layout& rgba) {
    for (std::size_t y = 0; y < rgba.height; ++y) {
        const std::uint8_t* p = rgba.row(y);
        for (std::size_t i = 3; i < rgba.row_bytes(); i += 4)
            if (p[i] != 255) return false;
    }
    return true;
}

/// RGBA rows to RGB rows, in place: every byte moves to a lower address, so
/// a forward copy never overwrites a byte it has yet to read.
Layout drop_alpha(const Layout& rgba) {
    Layout rgb = rgba;
    rgb.bpp = 3;
    for (std::size_t y = 0; y < rgba.height; ++y) {
        const std::uint8_t* src = rgba.row(y);
        std::uint8_t* dst = rgb.row(y);
        for (std::size_t x = 0; x < rgba.width; ++x, src += 4, dst += 3)
            dst[0] = src[0], dst[1] = src[1], dst[2] = src[2];
    }
    return rgb;
}

/// Appends rows [y0, y1) of `image` (unfiltered) to `out` as the file has
/// them, with `filter` (none or adaptive).
void append_filtered(const Layout& image, std::size_t y0, std::size_t y1, PngFilter filter,
                     std::vector<std::uint8_t>& out) {
    const std::size_t n = image.row_bytes();
    const std::vector<std::uint8_t> zeros(n, 0); // the row above the first
    for (std::size_t y = y0; y < y1; ++y) {
        const std::uint8_t* row = image.row(y);
        const std::uint8_t* above = y == 0 ? zeros.data() : image.row(y - 1);
        const int type =
            filter == PngFilter::none ? 0 : detail::best_png_filter(row, above, n, image.bpp);
        const std::size_t at = out.size();
        out.resize(at + n + 1);
        out[at] = std::uint8_t(type);
        detail::png_filter_row(type, row, above, n, image.bpp, out.data() + at + 1);
    }
}

/// Filters every row of `image` in place with `filter` (not automatic).
void filter_in_place(const Layout& image, PngFilter filter) {
    const std::size_t n = image.row_bytes();
    if (filter == PngFilter::none) {
        for (std::size_t y = 0; y < image.height; ++y) image.row(y)[-1] = 0;
        return;
    }
    // The unfiltered row above (zeros above the first) and this one.
    std::vector<std::uint8_t> above(n, 0), row(n);
    for (std::size_t y = 0; y < image.height; ++y) {
        std::uint8_t* out = image.row(y);
        std::copy(out, out + n, row.begin());
        const int type = filter == PngFilter::adaptive
                             ? detail::best_png_filter(row.data(), above.data(), n, image.bpp)
                             : int(filter);
        out[-1] = std::uint8_t(type);
        detail::png_filter_row(type, row.data(), above.data(), n, image.bpp, out);
        above.swap(row);
    }
}

struct CompressorFree {
    void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};
using Compressor = std::unique_ptr<libdeflate_compressor, CompressorFree>;

/// A zlib stream of `size` bytes at `data`: its bytes, at most the bound
/// of their count, and how many there are (0 on failure). The buffer is not
/// zeroed: only the pages the stream fills are ever touched.
struct Zlib {
    LargeBytes bytes; // huge pages (paint/large_buffer.h): the bound is about the image's size
    std::size_t size = 0;
};
Zlib compress(libdeflate_compressor* z, const std::uint8_t* data, std::size_t size) {
    const std::size_t bound = libdeflate_zlib_compress_bound(z, size);
    Zlib out{large_bytes(bound), 0};
    out.size = libdeflate_zlib_compress(z, data, size, out.bytes.get(), bound);
    return out;
}

// The sample `automatic` judges by: bands of kBandRows rows, kBands of them
// spread over the image (1/16 of a 1024 px high image; the trial costs two
// compressions of that). A smaller image is its own sample.
constexpr std::size_t kBandRows = 8, kBands = 8;
// Rendered pictures (flat fills, antialiased edges, gradients) compress
// best unfiltered: a row repeats or shifts the one above, which deflate
// matches whole, while filters chosen row by row break those repeats. The
// sample misjudges this: each band starts cold, and cold rows favour
// filters. So filtering is chosen only when it wins the sample clearly.
// Measured (bench/io/png_bench): the examples' gradients sample at 0.67 to
// 0.79 of the unfiltered size and compress whole 10-25% smaller unfiltered;
// the blurred filters example samples at 0.56 and whole at 0.61.
constexpr double kFilteredWins = 0.65;

/// `automatic`'s choice for an image, and the image's zlib stream when the
/// trial compressed all of it (a small image is its own sample: the stream
/// of the rows as the choice filters them), else an empty stream.
struct FilterChoice {
    PngFilter filter;
    Zlib stream;
};

/// `automatic`'s choice for `image` (unfiltered): none or adaptive.
FilterChoice choose_filter(const Layout& image, libdeflate_compressor* z) {
    const bool whole = image.height < 2 * kBandRows * kBands;
    const std::size_t bands = whole ? 1 : kBands, rows = whole ? image.height : kBandRows;
    std::vector<std::uint8_t> plain, filtered;
    for (std::size_t k = 0; k < bands; ++k) {
        const std::size_t y0 = whole ? 0 : k * (image.height - rows) / (bands - 1);
        append_filtered(image, y0, y0 + rows, PngFilter::none, plain);
        append_filtered(image, y0, y0 + rows, PngFilter::adaptive, filtered);
    }
    Zlib a = compress(z, plain.data(), plain.size());
    Zlib b = compress(z, filtered.data(), filtered.size());
    const bool filter = double(b.size) < (whole ? 1.0 : kFilteredWins) * double(a.size);
    FilterChoice choice{filter ? PngFilter::adaptive : PngFilter::none, {}};
    if (whole) choice.stream = std::move(filter ? b : a);
    return choice;
}

/// The image's zlib stream, filtered as `options` ask: under 128 rows the
/// automatic filter's trial stream itself, which was compressed twice already
/// (once a way); else the rows filtered in place and compressed.
Zlib filtered_stream(const Layout& image, const PngOptions& options, libdeflate_compressor* z) {
    FilterChoice choice = options.filter == PngFilter::automatic ? choose_filter(image, z)
                                                                 : FilterChoice{options.filter, {}};
    if (choice.stream.size > 0) return std::move(choice.stream);
    filter_in_place(image, choice.filter);
    return compress(z, image.bytes, image.height * (image.row_bytes() + 1));
}

/// The IDAT chunks of a zlib stream (PNG 11.2.4: the stream may be cut
/// anywhere), each of at most `chunk` bytes.
void put_idat(std::vector<std::uint8_t>& out, const Zlib& stream, std::size_t chunk) {
    for (std::size_t at = 0; at < stream.size; at += chunk)
        put_chunk(out, "IDAT", {stream.bytes.get() + at, std::min(chunk, stream.size - at)});
}

} // namespace

PngRows::PngRows(int width, int height)
    : bytes_(large_bytes(std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0)) * 4 +
                         std::size_t(std::max(height, 0)))),
      width_(std::max(width, 0)), height_(std::max(height, 0)) {}

std::vector<std::uint8_t> encode_png(PngRows&& rows, const PngOptions& options) {
    if (rows.width_ <= 0 || rows.height_ <= 0) return {};
    try {
        Layout image{rows.bytes_.get(), std::size_t(rows.width_), std::size_t(rows.height_), 4};
        if (opaque(image)) image = drop_alpha(image);
        const Compressor z(libdeflate_alloc_compressor(std::clamp(options.level, 1, 12)));
        if (!z) return {};
        const Zlib idat = filtered_stream(image, options, z.get());
        if (idat.size == 0) return {};
        // PNG 5.3: a chunk holds under 2^31 bytes.
        const std::size_t chunk =
            std::clamp(options.idat_bytes, std::size_t(1), PngOptions{}.idat_bytes);
        std::vector<std::uint8_t> out{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}; // PNG 5.2
        out.reserve(out.size() + 25 + 13 + 16 + 12 * (1 + idat.size / chunk) + idat.size + 12);
        std::uint8_t ihdr[13] = {}; // PNG 11.2.2
        put_u32(ihdr, std::uint32_t(rows.width_)), put_u32(ihdr + 4, std::uint32_t(rows.height_));
        ihdr[8] = 8;                        // bits a channel
        ihdr[9] = image.bpp == 4 ? 6 : 2;   // color type: RGBA or RGB
        put_chunk(out, "IHDR", ihdr);       // compression 0, filter method 0, no interlace
        const std::uint8_t intent[1] = {0}; // sRGB (11.3.3.5): perceptual rendering intent
        put_chunk(out, "sRGB", intent);
        std::uint8_t gamma[4];
        put_u32(gamma, 45455); // gAMA 1/2.2 times 100000, the value 11.3.3.5 gives with sRGB
        put_chunk(out, "gAMA", gamma);
        put_idat(out, idat, chunk);
        put_chunk(out, "IEND", {});
        return out;
    } catch (const std::bad_alloc&) {
        return {};
    }
}

std::vector<std::uint8_t> encode_png(std::span<const std::uint8_t> rgba, int width, int height,
                                     const PngOptions& options) {
    // PNG 11.2.2: width and height are at most 2^31 - 1; int holds no more.
    if (width <= 0 || height <= 0 || rgba.size() != std::size_t(width) * std::size_t(height) * 4)
        return {};
    try {
        PngRows rows(width, height);
        const std::size_t n = std::size_t(width) * 4;
        for (int y = 0; y < height; ++y)
            std::copy_n(rgba.data() + std::size_t(y) * n, n, rows.rgba(y));
        return encode_png(std::move(rows), options);
    } catch (const std::bad_alloc&) {
        return {};
    }
}

std::string write_png_atomic(const std::string& path, PngRows&& rows) {
    const int w = rows.width(), h = rows.height();
    if (w <= 0 || h <= 0)
        return path + ": cannot write a " + std::to_string(w) + " x " + std::to_string(h) + " PNG";
    const std::vector<std::uint8_t> png = encode_png(std::move(rows));
    if (png.empty())
        return path + ": cannot encode a " + std::to_string(w) + " x " + std::to_string(h) +
               " PNG (out of memory)";
    return write_file_atomic(path, {reinterpret_cast<const char*>(png.data()), png.size()});
}

} // namespace casteljau
