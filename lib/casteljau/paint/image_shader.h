// ImageShader: a RasterImage as a paint (SVG <image>, and image patterns).
//
// `to_device` maps image pixel space, where pixel (i, j) covers
// [i, i + 1] x [j, j + 1], to device pixels; the centre q = (x + 0.5, y + 0.5)
// of device pixel (x, y) samples the image at p = to_device^-1 q:
//   nearest  (image-rendering: optimizeSpeed, SVG 1.1 11.7; CSS Images 3
//            pixelated): the pixel that contains p, (floor(p.x), floor(p.y));
//   bilinear (the default, optimizeQuality): with pixel centres at integers,
//            u = p.x - 0.5 = i + s and v = p.y - 0.5 = j + t (0 <= s, t < 1),
//            (1 - t)((1 - s) P(i, j) + s P(i + 1, j))
//              + t((1 - s) P(i, j + 1) + s P(i + 1, j + 1)),
//            on premultiplied values, so that a transparent pixel's color
//            does not bleed into its neighbours.
// Outside the image, `repeat` tiles the plane (an index k becomes k mod W,
// floor-mod, so the interpolation crosses the seam to the other edge); pad,
// the alternative, extends the edge pixels (the point is clamped between the
// first and last pixel centres). Coordinates are reduced in double before
// they become indices, so huge or NaN coordinates still give a valid pixel.
//
// Shading is by rows (shade): a span's pixels in one call, each sampled at
// its own centre as above (never a point stepped along the row, which,
// rounded differently, could land on the other side of a pixel edge). Where
// the map does not rotate or skew, p.y is the same along the row, and so is
// the vertical half of the bilinear sample: computed once a row; where it
// keeps columns upright too, the horizontal half is the same for every row,
// and tabulate() computes it once a shape for the columns the shape covers
// (from the same expression: the same values). Then an image row sampled
// along those columns, (1 - s) P(i, j) + s P(i + 1, j), is the same for
// every device row that lies beside image row j: it is kept for the next
// device row, which shares one of its two image rows or both wherever the
// image is not scaled down, so that a device row samples one image row at
// most, not two (the frame of an image scaled by 2: 14% faster). Where the
// map is a translation by whole pixels (an image drawn at its own size on
// the pixel grid; a pattern tile drawn at the device resolution, whose side
// is a whole number of pixels), every pixel centre lands on an image pixel
// centre: both samplings give that pixel exactly (bilinear weights are 0),
// and it is copied; into an 8-bit canvas, an opaque image's bytes are
// copied (store_opaque). Where the image is scaled, a span of coverage 1 on
// an 8-bit canvas whose two kept image rows are opaque takes its samples
// quantized (store_opaque again): source-over of an opaque sample at
// coverage 1 is round(255 S + 0 D), the destination unread (the image at
// 2x: 0.75 against 1.20x Cairo's time, bench/README.md).
#pragma once

#include "casteljau/geom/affine.h"
#include "casteljau/paint/canvas.h"
#include "casteljau/paint/color.h"
#include "casteljau/paint/raster_image.h"
#include "casteljau/raster/span.h"

#include <array>
#include <vector>

namespace casteljau {

/// An image ready to shade device pixels: the device -> image map and the
/// sampling options. The image must outlive the shader's use. One thread a
/// shader: shade() keeps the image rows it sampled for the next row.
class ImageShader {
  public:
    /// `to_device` maps image pixel space to device pixels. Samples by
    /// bilinear interpolation when `smooth`, else the nearest pixel; tiles
    /// the plane when `repeat`, else extends the edge pixels. False, and
    /// nothing is painted, when the image is empty or the map singular.
    bool prepare(const RasterImage& image, const Affine& to_device, float opacity, bool smooth,
                 bool repeat);
    /// Where the map keeps rows level and columns upright (a scale and a
    /// translation) and samples bilinearly: the horizontal half of the
    /// samples of device columns [x0, x1) (the same for every row), computed
    /// now, once, and read by shade() from then on. Until the next prepare().
    void tabulate(int x0, int x1);
    /// The premultiplied color at the centre of device pixel (x, y), times the opacity.
    Premul at(int x, int y) const;
    /// at(x + i, y) into out[i] for i in [0, n): the same values, a row at a time.
    void shade(int x, int y, int n, Premul* out) const;
    /// Where source-over at coverage 1 of the n pixels from device pixel
    /// (x, y) needs no destination, writes the bytes it would give into out
    /// and returns true; else writes nothing and returns false. That is at
    /// opacity 1 where the map translates by whole pixels and the image
    /// carries opaque8 (raster_image.h; the bytes copied), and where the
    /// columns are tabulated and both image rows sampled along them are
    /// opaque (each sample's alpha is then exactly 1: its quantized color
    /// is the composite).
    bool store_opaque(int x, int y, int n, Premul8* out) const;

  private:
    /// shade() where the map translates by whole pixels: the pixels copied.
    void copy_row(int x, int y, int n, Premul* out) const;
    /// The stretches of `pixels` (the image's, or its opaque8) that device
    /// row y, columns [x, x + n) take where the map translates by whole
    /// pixels, each given as copy(from, m, k): m pixels from `from` to the
    /// row's k-th on.
    template <class P, class Copy>
    void copy_stretches(const std::vector<P>& pixels, int x, int y, int n, Copy&& copy) const;

  public:
    /// The two pixels a bilinear sample lies between along one axis, and
    /// the weight of the second.
    struct Axis {
        int i0 = 0, i1 = 0; ///< the two pixels' indices
        float t = 0;        ///< the weight of i1, in [0, 1]
    };

  private:
    const RasterImage* image_ = nullptr;
    Affine inverse_;               // device -> image pixel space
    double inv_w_ = 1, inv_h_ = 1; // 1 / width, 1 / height: wrapping multiplies
    float opacity_ = 1;
    bool smooth_ = true, repeat_ = false;
    bool aligned_ = false; // inverse_ translates by whole pixels: (shift_x_, shift_y_)
    long long shift_x_ = 0, shift_y_ = 0;
    // tabulate()'s columns: columns_[i] is device column columns_x0_ + i's axis.
    std::vector<Axis> columns_;
    int columns_x0_ = 0;
    // Image rows sampled along the tabulated columns (the horizontal half
    // of the bilinear sample, top of the file): pixels[c] for the columns
    // c in [lo, hi) of columns_, of image row `row` (-1: none). Two, the
    // rows a device row lies between; the next device row usually shares
    // one or both (mutable: a cache, the values are shade()'s).
    struct Along {
        std::vector<Premul> pixels;
        int row = -1, lo = 0, hi = 0;
        bool opaque = false; ///< every alpha in [lo, hi) is exactly 1
    };
    mutable std::array<Along, 2> along_;
    /// Image row j sampled along columns [lo, hi) of columns_ (pixels
    /// indexed by column), from the slot holding it or the one not holding
    /// row `keep`.
    const Along& along(int j, int keep, int lo, int hi) const;
    /// The two image rows a level map samples for device row y's columns
    /// [x, x + n), sampled along the tabulated columns, and the weight of
    /// the second (top[i] and bottom[i] are pixel x + i's).
    struct LevelRows {
        const Premul *top = nullptr, *bottom = nullptr;
        float t = 0;
        bool opaque = false; ///< every alpha of both is exactly 1
    };
    /// LevelRows into r where the map is level and those columns are
    /// tabulated; else false.
    bool level_rows(int x, int y, int n, LevelRows& r) const;
};

/// Image compositing.
template <class Pixel>
using ImageSpanPainter = ShadedSpanPainter<Pixel, ImageShader>;

} // namespace casteljau
