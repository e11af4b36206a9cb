// ImageLevels: an image's mip levels, which stand in for it where it is
// drawn smaller than half its size.
//
// Why: a bilinear sample reads the 2 x 2 pixels around one point. Drawn at an
// eighth of its size, an image has 64 pixels under each device pixel and the
// sample reads 4 of them: thin lines break up or vanish, fine patterns turn
// into moire (the tiger drawn from a 2048 px PNG at 256 px: 21.8% of the
// pixels differed from rsvg-convert's, the whiskers gone). Browsers sample a
// level made by halving instead (Skia's mipmaps; Chromium picks the level in
// cc/tiles/mipmap_util.cc); Cairo, and so rsvg-convert, filters over each
// device pixel's footprint (its GOOD filter: a box as wide as the scale).
//
// Level k is the image (level 0) shrunk to max(1, w >> k) x max(1, h >> k)
// by an area filter: along an axis of n pixels shrunk to m, output pixel i
// covers [i r, (i + 1) r) of the input, r = n / m, and is the mean of the
// input over it,
//     out(i) = sum_j |[j, j + 1] intersect [i r, (i + 1) r]| / r * in(j),
// separably (the rows under an output row weighed together, then its
// columns), on premultiplied values (a transparent pixel's color does not
// bleed). An output's weights sum to 1, and every input's area is given out
// whole (its weights sum to 1 / r): a level has the image's mean. Where n is
// a multiple of 2^k, r = 2^k and the weights are 2^-k each: level k of an
// image of 2^k x 2^k blocks is each block's mean, as Cairo's box filter
// draws it at 2^-k. Each level is made from level 0 directly, not by
// halving the one before: the image is read once, the levels between are
// neither written nor read (a 2048 px image's level 3: 10 ms, about 25 by
// halvings), and odd sides are not rounded down twice.
//
// Which level (level_for): the map's scale along each of the image's axes
// (device pixels per image pixel, the lengths of the map's columns), the
// larger of the two (the axis shrunk least, so that the other is not blurred
// past it); level k = floor(log2(1 / scale)), the smallest level still at
// least the size drawn (as Chromium's): it is then shrunk by less than 2,
// where a bilinear sample still reads every pixel at least once. Drawn at
// its size or larger, level 0, the image. An image shrunk along one axis
// only (a wide image squeezed into a square) is filtered by its other axis
// alone and may still alias along the first: a level per axis pair (a
// rip-map) would cost four times the image's memory.
//
// Memory: the levels of a w x h image hold at most w h / 3 pixels (a
// quarter, a sixteenth, ...), built on first use: an image never drawn
// smaller than half its size builds none.
#pragma once

#include "casteljau/geom/affine.h"

#include <memory>
#include <mutex>
#include <vector>

namespace casteljau {

struct RasterImage;

/// An image's levels past level 0, built on first use and kept; safe to
/// read from several threads at once (the first builds, the others wait).
/// A copy does not share them: its pixels may be changed before it draws.
class ImageLevels {
  public:
    ImageLevels() noexcept;
    /// None of `other`'s levels: built again, from the copy's pixels.
    ImageLevels(const ImageLevels& other) noexcept;
    /// Forgets the levels built: the pixels assigned with them are others.
    ImageLevels& operator=(const ImageLevels& other) noexcept;
    ~ImageLevels();

    /// Level k >= 1 of `image` (whose member this is), k clamped to the
    /// last level (1 x 1). The image's pixels must be final.
    const RasterImage& get(const RasterImage& image, int k) const;

  private:
    mutable std::mutex mutex_;
    mutable std::vector<std::unique_ptr<RasterImage>> levels_; // level k at k - 1, or null
};

/// `image` shrunk to w x h (1 <= w, h, at most its size) by the area filter
/// above.
RasterImage shrink_by_area(const RasterImage& image, int w, int h);

/// The levels past level 0 of a w x h image: halvings until 1 x 1.
int last_level(int w, int h);

/// The level to sample bilinearly where `to_device` maps a w x h image's
/// pixel space to device pixels (the choice above): 0 where it is drawn at
/// half its size or larger, or the map is singular or not finite.
int level_for(const Affine& to_device, int w, int h);

} // namespace casteljau
