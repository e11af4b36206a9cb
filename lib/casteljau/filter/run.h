// Running a filter graph on a layer (Filter Effects 1, 9).
//
// The renderer draws the filtered element into a layer (SourceGraphic),
// hands it here with what the graph's feImage and FillPaint/StrokePaint
// inputs need drawn, and gets the filter's result back in the same layer.
// Everything happens in device pixels: user-space parameters are mapped by
// the element's transform (lengths scaled by the transform's x and y
// stretch, points and offsets mapped). Under rotation or skew the blur,
// morphology and convolution kernels stay aligned with the device axes,
// not the user axes (a documented approximation: resvg draws rotated
// filters into an axis-aligned user-space layer and resamples it instead).
//
// Memory: every intermediate result is an image of the window's size; a
// result is freed after the last primitive that reads it, and a run that
// would hold more than kMaxFilterBytes at once fails (the element is not
// drawn, as for a filter in error). So does a graph of more than
// kMaxFilterPrimitives primitives.
#pragma once

#include "casteljau/filter/graph.h"
#include "casteljau/geom/affine.h"

#include <cstddef>
#include <span>

namespace casteljau {

/// The most bytes of intermediate images one run holds at once (1 GiB:
/// sixty-four 2048 x 2048 float images). A run over it draws nothing.
inline constexpr std::size_t kMaxFilterBytes = std::size_t(1) << 30;
/// How many images a run of `g` holds at once, at most: the results alive
/// together (each until its last reader) and the run's six temporaries.
/// Checked against kMaxFilterBytes before any work.
std::size_t filter_held_images(const FilterGraph& g);
/// The most primitives in one filter (browsers have no limit; 4096 is some
/// hundred times what real files use, and bounds the time of a hostile one).
inline constexpr std::size_t kMaxFilterPrimitives = 4096;

/// What a run reads and writes. All images have the same box (the window).
struct FilterSources {
    FilterImage* source = nullptr;             ///< SourceGraphic in, the result out; sRGB both
    std::span<const FilterImage> images = {};  ///< feImage drawings (ImageInput::index), sRGB
    const FilterImage* fill_paint = nullptr;   ///< FillPaint, sRGB; transparent when null
    const FilterImage* stroke_paint = nullptr; ///< StrokePaint, sRGB; transparent when null
    /// Spare images whose storage a run reuses and leaves there for the
    /// next (a renderer keeps one per thread); optional.
    std::vector<FilterImage>* pool = nullptr;
};

/// Runs `g` with user space mapped to the device by `to_device`. False when
/// the filter is in error or over a limit: then nothing is to be drawn
/// (Filter Effects 1, 8.3), and the source is left cleared.
bool run_filter(const FilterGraph& g, const Affine& to_device, const FilterSources& io);

/// How far (device px) the result at a pixel can depend on the source
/// away from it: infinity for primitives that read far (feTile, edge modes
/// duplicate and wrap). Computing a window grown by this much around the
/// pixels wanted gives those pixels exactly.
double filter_reach(const FilterGraph& g, const Affine& to_device);

/// The filter region on the device: a box of whole pixels (outward).
PixelRect filter_pixel_region(const FilterGraph& g, const Affine& to_device);

/// A user-space box mapped by `m`, rounded outward to whole pixels
/// (corners mapped: conservative under rotation); empty when `r` is.
PixelRect device_pixels(const Rect& r, const Affine& m);

} // namespace casteljau
