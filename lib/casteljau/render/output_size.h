// The size of the image a document is rendered to: from a requested width,
// height or scale (or the document's own size), within the output limits.
//
// Shared by every front end (the CLI's render command, the Python package),
// so that the same request gives the same pixels and the same refusal
// everywhere. A requested width or height keeps the aspect ratio; each side
// is the scaled document size rounded up (less 1e-9, so that a product that
// should be whole and is off by rounding does not gain a pixel). The limits
// are checked before anything is allocated: 16384 px a side, 2^26 pixels
// in all (a 1 GiB float canvas).
#pragma once

#include <string>

namespace casteljau {

/// Largest output side, pixels.
inline constexpr int kMaxOutputSide = 16384;
/// Most output pixels in all (2^26, 64 Mpx: a 1 GiB float canvas).
inline constexpr double kMaxOutputPixels = double(1 << 26);

/// What the caller asked for: at most one of these above 0; none means scale 1.
struct SizeRequest {
    double width = 0;  ///< output width, px; the height follows the aspect ratio
    double height = 0; ///< output height, px; the width follows the aspect ratio
    double scale = 0;  ///< factor from the document size
};

/// An output size and the scale that maps the document onto it, or why there is none.
struct OutputSize {
    int width = 0, height = 0; ///< pixels; 0 when `error` is set
    double scale = 1;          ///< document px to output px (Affine::scale(scale))
    /// Empty when the size is within the limits, else "output size W x H px
    /// is outside the limits (...)".
    std::string error;
};

/// The output size of a document of `doc_width` x `doc_height` px for `request`.
OutputSize output_size(double doc_width, double doc_height, const SizeRequest& request);

} // namespace casteljau
