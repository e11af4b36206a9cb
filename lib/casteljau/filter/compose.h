// The compositing family of filter primitives (Filter Effects 1): feFlood
// (15.14), feOffset (15.19), feBlend (15.5), feComposite (15.8), feMerge
// (15.18), feTile (15.22), and feDropShadow (15.13) built from them.
#pragma once

#include "casteljau/filter/graph.h"

#include <span>

namespace casteljau {

/// feFlood: `color` (premultiplied, in out's space) over all of `sub`.
void flood(FilterImage& out, const Subregion& sub, const Premul& color);

/// feOffset: out(x, y) = in(x - dx, y - dy), whole device pixels.
void offset(const FilterImage& in, FilterImage& out, const Subregion& sub, int dx, int dy);

/// feBlend: `in` (the source) blended onto `in2` (the backdrop) with `mode`.
void blend(const FilterImage& in, const FilterImage& in2, FilterImage& out, const Subregion& sub,
           BlendMode mode);

/// feComposite: `in` composited with `in2` by the Porter-Duff operator or
/// the arithmetic k1 i1 i2 + k2 i1 + k3 i2 + k4 (clamped), on premultiplied channels.
void composite(const FilterImage& in, const FilterImage& in2, FilterImage& out,
               const Subregion& sub, const Composite& c);

/// feMerge: each input source-over the ones before it.
void merge(std::span<const FilterImage* const> inputs, FilterImage& out, const Subregion& sub);

/// feTile: the rectangle `tile` of `in` (window coordinates; it may reach
/// beyond the window, where it is transparent) repeated over `sub`.
void tile(const FilterImage& in, const Subregion& tile, FilterImage& out, const Subregion& sub);

} // namespace casteljau
