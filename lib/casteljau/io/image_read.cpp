// Decoding PNG (libpng, io/detail/png_read.h), JPEG (libjpeg,
// io/detail/jpeg_read.h), WebP (libwebp, io/detail/webp_read.h), GIF, TIFF
// and animated WebP (OpenImageIO, through its module:
// io/detail/oiio_module.h) into premultiplied float RasterImages.
//
// Format: found from the signature (PNG, ISO/IEC 15948 5.2; JPEG's SOI
// marker FF D8 FF, ITU T.81 B.1.1.3; GIF87a/GIF89a, GIF89a 17; RIFF....WEBP,
// RFC 9649 2.5; TIFF 6.0 2, "II*\0"/"MM\0*", and BigTIFF's 43), and only that
// format's reader is asked: OIIO's own open() would try every reader it has
// (RAW, DICOM, FFmpeg...) on bytes that came from an SVG.
//
// Size: the pixel limit is checked before any pixel is decoded. The PNG and
// JPEG readers and OIIO 2.4's TIFF reader read only the header when
// opened; OIIO's GIF reader allocates the whole canvas then, and its WebP
// reader decodes the whole
// image, so for those two the size is read from the header first: GIF's
// logical screen (GIF89a 18), WebP's canvas (VP8X), lossless (VP8L, RFC 9649
// 3.2.1) or lossy frame (VP8, RFC 6386 9.1) size.
//
// Alpha: the canvas holds premultiplied sRGB-encoded values (paint/color.h).
// Left alone, OIIO premultiplies straight alpha itself, in the file's 8 or 16
// bits; so the readers are asked to keep straight alpha ("oiio:Unassociated
// Alpha" hint), which those that honour it (PNG, TIFF) report with the same
// attribute, and the values are premultiplied here in float. A reader that
// reports nothing delivers associated alpha (a TIFF whose ExtraSamples says
// associated; OIIO 2.4's WebP reader, which always premultiplies), or none:
// its values are taken as they are.
//
// Orientation: the EXIF/TIFF Orientation tag (TIFF 6.0, 8; EXIF 2.32 4.6.4A)
// says where the stored rows and columns go; browsers apply it (CSS Images 3,
// image-orientation: from-image, the initial value), and so does this reader.
#include "casteljau/io/image_read.h"

#include "casteljau/io/detail/jpeg_read.h"
#include "casteljau/io/detail/oiio_module.h"
#include "casteljau/io/detail/png_read.h"
#include "casteljau/io/detail/webp_read.h"

#include <algorithm>
#include <cstdint>
#include <exception>
#include <fstream>
#include <optional>
#include <string_view>
#include <utility>

namespace casteljau {

namespace {

// Enough bytes for every signature and for the WebP frame size at 26..29.
constexpr std::size_t kHeadBytes = 32;

/// The OIIO reader for the signature at the start of `h`, or null.
const char* sniff_format(std::span<const unsigned char> h) {
    const auto at = [&](std::size_t offset, std::string_view sig) {
        return h.size() >= offset + sig.size() &&
               std::equal(
                   sig.begin(), sig.end(), h.begin() + std::ptrdiff_t(offset),
                   [](char s, unsigned char b) { return static_cast<unsigned char>(s) == b; });
    };
    using namespace std::string_view_literals;
    if (at(0, "\x89PNG\r\n\x1a\n"sv)) return "png";
    if (at(0, "\xff\xd8\xff"sv)) return "jpeg";
    if (at(0, "GIF87a"sv) || at(0, "GIF89a"sv)) return "gif";
    if (at(0, "RIFF"sv) && at(8, "WEBP"sv)) return "webp";
    if (at(0, "II*\0"sv) || at(0, "MM\0*"sv) || at(0, "II+\0"sv) || at(0, "MM\0+"sv)) return "tiff";
    return nullptr;
}

/// Width and height as a GIF or WebP header declares them (see above), or
/// nullopt when the header is cut short or not one this reads.
std::optional<std::pair<std::uint64_t, std::uint64_t>>
declared_size(std::string_view format, std::span<const unsigned char> h) {
    const auto le = [&](std::size_t i, int bytes) {
        std::uint64_t v = 0;
        for (int k = bytes - 1; k >= 0; --k) v = v << 8 | h[i + std::size_t(k)];
        return v;
    };
    if (format == "gif") {
        if (h.size() < 10) return std::nullopt;
        return std::pair{le(6, 2), le(8, 2)};
    }
    if (h.size() < 30) return std::nullopt;
    const std::string_view chunk(reinterpret_cast<const char*>(h.data()) + 12, 4);
    if (chunk == "VP8X") return std::pair{le(24, 3) + 1, le(27, 3) + 1};
    if (chunk == "VP8L") {
        const std::uint64_t bits = le(21, 4);
        return std::pair{(bits & 0x3fff) + 1, (bits >> 14 & 0x3fff) + 1};
    }
    if (chunk == "VP8 ") return std::pair{le(26, 2) & 0x3fff, le(28, 2) & 0x3fff};
    return std::nullopt;
}

std::string size_error(std::uint64_t w, std::uint64_t h, std::size_t max_pixels) {
    return "image of " + std::to_string(w) + " x " + std::to_string(h) +
           " pixels exceeds the limit of " + std::to_string(max_pixels) + " pixels";
}

/// An OIIO error on one line: OIIO joins its messages with newlines.
std::string one_line(const std::string& message) {
    std::string out;
    for (char c : message) {
        if (c != '\n')
            out += c;
        else if (!out.empty())
            out += "; ";
    }
    while (out.ends_with("; ")) out.resize(out.size() - 2);
    return out;
}

/// A float from a file, in [0, 1]; NaN becomes 0. Integer formats give
/// [0, 1] already; a float TIFF may hold anything.
float unit(float v) { return v >= 0 ? std::min(v, 1.0f) : 0.0f; }

/// `in` displayed as its EXIF orientation (1 to 8) says. Output pixel (x, y)
/// comes from stored pixel (sx, sy) with (a, b) = (y, x) when the tag says
/// rows and columns are exchanged (5 to 8), else (x, y); then sx = a or
/// W - 1 - a, sy = b or H - 1 - b, as the tag's mirrorings say.
RasterImage oriented(const RasterImage& in, int orientation) {
    const bool swap = orientation >= 5;
    const bool flip_x =
        orientation == 2 || orientation == 3 || orientation == 7 || orientation == 8;
    const bool flip_y =
        orientation == 3 || orientation == 4 || orientation == 6 || orientation == 7;
    RasterImage out;
    out.width = swap ? in.height : in.width;
    out.height = swap ? in.width : in.height;
    out.pixels.resize(in.pixels.size());
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            const int a = swap ? y : x, b = swap ? x : y;
            out.pixels[std::size_t(y) * std::size_t(out.width) + std::size_t(x)] =
                in.at(flip_x ? in.width - 1 - a : a, flip_y ? in.height - 1 - b : b);
        }
    return out;
}

/// An image opened for reading, or the error.
struct Opened {
    std::unique_ptr<detail::ImageReader> reader;
    std::string error;
};

/// PNG, JPEG and WebP (but animations) with the library's own readers,
/// every other format with OIIO's (its module loaded on first use).
Opened open_reader(const char* format, const std::string& name,
                   std::span<const unsigned char> memory, bool from_memory) {
    if (std::string_view(format) == "png") {
        detail::PngOpened png = detail::open_png(name, memory, from_memory);
        if (!png.reader) return {nullptr, "cannot decode: " + png.error};
        return {std::move(png.reader), {}};
    }
    if (std::string_view(format) == "jpeg") {
        detail::JpegOpened jpeg = detail::open_jpeg(name, memory, from_memory);
        if (!jpeg.reader) return {nullptr, "cannot decode: " + jpeg.error};
        return {std::move(jpeg.reader), {}};
    }
    if (std::string_view(format) == "webp") {
        detail::WebpOpened webp = detail::open_webp(name, memory, from_memory);
        if (webp.reader) return {std::move(webp.reader), {}};
        if (!webp.animated) return {nullptr, "cannot decode: " + webp.error};
    }
    const detail::OiioModule& oiio = detail::oiio_module();
    if (!oiio.codec) return {nullptr, detail::oiio_missing(std::string("decoding ") + format)};
    detail::OiioOpened opened = oiio.codec->open(format, name, memory, from_memory, true);
    if (!opened.reader)
        return {nullptr, (opened.no_reader ? std::string("no ") + format + " reader: "
                                           : std::string("cannot decode: ")) +
                             one_line(opened.error)};
    return {std::move(opened.reader), {}};
}

/// Decodes with the reader that `head` (the first bytes) calls for, from
/// the file `name` or, when `from_memory`, from `memory`. Errors without a
/// source.
ImageReadResult decode(std::span<const unsigned char> head, const std::string& name,
                       std::span<const unsigned char> memory, bool from_memory,
                       std::size_t max_pixels) {
    ImageReadResult r;
    const char* format = sniff_format(head);
    if (!format) {
        r.error = "not a PNG, JPEG, GIF, WebP or TIFF image";
        return r;
    }
    if (std::string_view(format) == "gif" || std::string_view(format) == "webp") {
        const auto size = declared_size(format, head);
        if (!size) {
            r.error = std::string("unreadable ") + format + " header";
            return r;
        }
        if (size->first * size->second > max_pixels) {
            r.error = size_error(size->first, size->second, max_pixels);
            return r;
        }
    }
    // Decoders throw too (OIIO 2.4's GIF reader: std::length_error on a
    // 65535 x 65535 screen), and allocations can fail.
    try {
        Opened opened = open_reader(format, name, memory, from_memory);
        if (!opened.reader) {
            r.error = std::move(opened.error);
            return r;
        }
        const detail::ImageHeader& spec = opened.reader->header();
        if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.channels <= 0) {
            r.error = "image of " + std::to_string(spec.width) + " x " +
                      std::to_string(spec.height) + " x " + std::to_string(spec.depth) +
                      " pixels and " + std::to_string(spec.channels) + " channels not supported";
            return r;
        }
        const std::uint64_t w = std::uint64_t(spec.width), h = std::uint64_t(spec.height);
        if (w * h > max_pixels) {
            r.error = size_error(w, h, max_pixels);
            return r;
        }
        const bool straight = spec.straight;
        const int orientation = spec.orientation;
        RasterImage img;
        img.width = spec.width, img.height = spec.height;
        img.pixels.resize(std::size_t(w * h));
        // Straight into the Premul pixels, each channel to its float: gray
        // lands in r (and alpha in g), expanded below.
        const int channels = std::min(spec.channels, 4);
        if (std::string e = opened.reader->read(
                channels, reinterpret_cast<float*>(img.pixels.data()), sizeof(Premul));
            !e.empty()) {
            r.error = "cannot decode: " + one_line(e);
            return r;
        }
        for (Premul& p : img.pixels) {
            float red = unit(p.r), green = unit(p.g), blue = unit(p.b), alpha = unit(p.a);
            if (channels <= 2) alpha = channels == 2 ? green : 1.0f, green = blue = red;
            if (channels == 3) alpha = 1.0f;
            // Straight: premultiply. Associated: a color above its alpha has
            // no meaning; it is clamped so that compositing stays in range.
            const auto premul = [&](float c) { return straight ? c * alpha : std::min(c, alpha); };
            p = {premul(red), premul(green), premul(blue), alpha};
        }
        if (orientation >= 2 && orientation <= 8) img = oriented(img, orientation);
        r.image = std::make_shared<const RasterImage>(std::move(img));
    } catch (const std::exception& e) {
        r.error = std::string("decoder failed: ") + e.what();
    }
    return r;
}

} // namespace

ImageReadResult read_image_file(const std::string& path, std::size_t max_pixels) {
    unsigned char head[kHeadBytes];
    std::ifstream file(path, std::ios::binary);
    if (!file) return {nullptr, path + ": cannot open the file"};
    file.read(reinterpret_cast<char*>(head), kHeadBytes);
    if (file.bad()) return {nullptr, path + ": cannot read the file"};
    ImageReadResult r = decode({head, std::size_t(file.gcount())}, path, {}, false, max_pixels);
    if (!r.error.empty()) r.error = path + ": " + r.error;
    return r;
}

bool decodes_without_openimageio(const std::string& path) {
    unsigned char head[kHeadBytes];
    std::ifstream file(path, std::ios::binary);
    file.read(reinterpret_cast<char*>(head), kHeadBytes);
    if (!file && !file.eof()) return false;
    const char* format = sniff_format({head, std::size_t(file.gcount())});
    if (!format) return false;
    const std::string_view f(format);
    return f == "png" || f == "jpeg" || f == "webp";
}

ImageReadResult decode_image(std::span<const unsigned char> bytes, std::size_t max_pixels) {
    return decode(bytes.first(std::min(bytes.size(), kHeadBytes)), "memory", bytes, true,
                  max_pixels);
}

} // namespace casteljau
