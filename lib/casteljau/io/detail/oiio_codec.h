// The interface between the library and its OpenImageIO module.
//
// OpenImageIO and the ~260 shared libraries it needs take about 200 ms to
// load, longer than most renders; so the library does not link it. Every use
// of OIIO sits behind this interface, implemented by the separate module
// libcasteljau_oiio.so (io/oiio/oiio_codec.cpp), which io/detail/oiio_module.h
// finds and loads on first use. The module is a thin adapter: which values
// are written, and what a decoded file's values mean, is decided by the
// library (io/image_write.cpp, io/image_read.cpp, render3d/texture.cpp).
//
// The module is built from the same sources as the library it is loaded
// into; the entry point's name carries the interface's version, so that a
// module of another version is not found rather than misused. Change the
// version with any change to the classes below.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace casteljau::detail {

/// The symbol the module exports: `const OiioCodec* casteljau_oiio_codec_v2()`.
inline constexpr const char* kOiioEntry = "casteljau_oiio_codec_v2";

/// The 8- and 16-bit sample scales of OIIO's integer-to-float conversion
/// (convert_type: v * (1 / max)); the library's own readers use them too,
/// so that their floats are the ones OIIO gave.
inline constexpr float kSampleScale8 = 1.0f / 255.0f, kSampleScale16 = 1.0f / 65535.0f;

/// What a reader reports of an opened image (its first subimage).
/// (ImageHeader and ImageReader serve the library's own PNG, JPEG and WebP
/// readers too: io/detail/png_read.h, jpeg_read.h, webp_read.h.)
struct ImageHeader {
    int width = 0, height = 0, depth = 0, channels = 0;
    /// The color is straight (the reader honoured the request to keep
    /// straight alpha, "oiio:UnassociatedAlpha").
    bool straight = false;
    /// The EXIF/TIFF orientation, 1 (as stored) to 8.
    int orientation = 1;
    /// The values are scene-linear ("oiio:ColorSpace" is "Linear").
    bool linear = false;
};

/// An opened image file, read once.
class ImageReader {
  public:
    virtual ~ImageReader() = default;
    virtual const ImageHeader& header() const = 0;
    /// Reads the first `channels` channels of every pixel as float, pixel i
    /// at out + i * `stride` bytes; "" or OIIO's error.
    virtual std::string read(int channels, float* out, std::size_t stride) = 0;
};

/// The result of OiioCodec::open.
struct OiioOpened {
    std::unique_ptr<ImageReader> reader; ///< null on error
    std::string error;                   ///< OIIO's message
    bool no_reader = false;              ///< OIIO has no reader for the format at all
};

/// Pixels to encode (TIFF, EXR): 4 values a pixel (floats or bytes), rows from the top.
struct OiioImage {
    int width = 0, height = 0;
    bool float_file = false;   ///< store 32-bit float, else 8 bits a channel
    bool float_pixels = false; ///< `pixels` holds floats, else bytes
    const void* pixels = nullptr;
    bool straight = true; ///< labelled straight alpha, else associated
    bool linear = false;  ///< labelled scene-linear, else sRGB
};

/// What the module does.
class OiioCodec {
  public:
    /// Opens an image with the reader of `format` (OIIO's name: "png",
    /// "jpeg", ...), or, when `format` is null, whichever reader the file
    /// calls for. From `memory` when `from_memory`, else from the file
    /// `name`. With `keep_straight` the reader is asked to keep straight
    /// alpha; otherwise OIIO premultiplies it.
    virtual OiioOpened open(const char* format, const std::string& name,
                            std::span<const unsigned char> memory, bool from_memory,
                            bool keep_straight) const = 0;
    /// Encodes `image` in the format `target`'s extension names, into
    /// `memory` when it is not null, else into the file `target`. "" or what
    /// went wrong, without the path.
    virtual std::string write(const std::string& target, const OiioImage& image,
                              std::vector<unsigned char>* memory) const = 0;

  protected:
    ~OiioCodec() = default;
};

} // namespace casteljau::detail
