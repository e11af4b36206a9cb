// Encoding 8-bit straight RGBA pixels as PNG (ISO/IEC 15948:2004, the PNG
// specification, second edition), without OpenImageIO: the format most
// renders are written in gets an encoder that costs no library start-up and
// compresses with libdeflate.
//
// The file: the signature, IHDR (8 bits a channel, not interlaced), sRGB and
// gAMA (the values are sRGB-encoded; 11.3.3.5 asks for gAMA next to sRGB for
// decoders that ignore sRGB), the zlib stream in IDAT chunks (of 1 GiB at most),
// IEND. Color type 6 (RGBA), or 2 (RGB) when every pixel is opaque: the
// decoded pixels are the same, the file is smaller.
//
// Filters (9, 12.8; io/detail/png_filter.h): by default the image is left
// unfiltered, which suits rendered pictures best (flat fills and edges
// repeat from row to row, and deflate matches them whole), unless filtering
// every row with the heuristic's choice compresses a sample of the rows
// clearly smaller (blurs, photographs). One type may be asked for instead.
//
// The rows are filled in place (PngRows) and filtered in place, so that
// writing a canvas touches one image-sized buffer besides the canvas: on a
// 1024 px image each 4 MB buffer costs about a thousand page faults, or two
// where the kernel gives it huge pages (paint/large_buffer.h).
#pragma once

#include "casteljau/paint/large_buffer.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace casteljau {

/// The row filter (PNG 9.2); `adaptive`: the best of the five for each row
/// by the heuristic; `automatic`: `none`, or `adaptive` for the whole image
/// when it compresses a sample of its rows clearly smaller.
enum class PngFilter { none, sub, up, average, paeth, adaptive, automatic };

/// How a PNG is compressed.
struct PngOptions {
    /// libdeflate's level, 1 (fastest) to 12 (smallest). 4: every example
    /// and the tiger within 1.07x of rsvg-convert's PNG size (level 3:
    /// 1.16x) for a few percent more time (bench/io/png_bench).
    int level = 4;
    PngFilter filter = PngFilter::automatic;
    /// Most bytes of the zlib stream an IDAT chunk holds (PNG 5.3: under
    /// 2^31), 1 to 2^30; decoders join the chunks, so only tests, which
    /// check that, need it smaller.
    std::size_t idat_bytes = std::size_t(1) << 30;
};

/// An image's rows, to be filled with straight RGBA and encoded. The
/// memory is left as allocated (not zeroed): fill every row.
class PngRows {
  public:
    /// Throws std::bad_alloc when the memory cannot be had.
    PngRows(int width, int height);
    int width() const { return width_; }   ///< pixels a row
    int height() const { return height_; } ///< rows
    /// Row y's width * 4 bytes, R G B A a pixel, straight (not premultiplied).
    std::uint8_t* rgba(int y) { return bytes_.get() + std::size_t(y) * stride() + 1; }

  private:
    friend std::vector<std::uint8_t> encode_png(PngRows&& rows, const PngOptions& options);
    std::size_t stride() const { return std::size_t(width_) * 4 + 1; }
    // Each row: a byte for its filter type, then its pixels.
    LargeBytes bytes_; // huge pages: paint/large_buffer.h
    int width_ = 0, height_ = 0;
};

/// The bytes of a PNG file of `rows`, which are consumed (filtered in
/// place). Empty when memory runs out.
std::vector<std::uint8_t> encode_png(PngRows&& rows, const PngOptions& options = {});

/// The same for `width` x `height` straight RGBA pixels (4 bytes a pixel,
/// rows from the top, no padding). Empty when the sizes are not positive or
/// disagree with `rgba`, or memory runs out.
std::vector<std::uint8_t> encode_png(std::span<const std::uint8_t> rgba, int width, int height,
                                     const PngOptions& options = {});

/// encode_png written to `path` atomically (atomic_file.h); "" or
/// "PATH: what went wrong".
std::string write_png_atomic(const std::string& path, PngRows&& rows);

} // namespace casteljau
