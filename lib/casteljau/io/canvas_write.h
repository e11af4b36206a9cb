// Writing a Canvas as an image file, in the encoding its format expects:
// * 8-bit formats (PNG, JPEG, ...) and TIFF: straight (un-premultiplied)
//   sRGB-encoded values, the SVG color space, converted by
//   paint/straight_rgba.h (which also rounds the 8-bit ones, so that a PNG
//   holds exactly the bytes straight_rgba8 gives any other caller); TIFF is
//   written as float and tagged unassociated alpha. Straight rather than the
//   canvas's premultiplied values: PNG can only store straight ones, and
//   dividing in float keeps the precision that dividing 8-bit values would lose.
// * EXR: scene-linear, premultiplied, float, as OpenEXR files are by
//   convention (the sRGB transfer function is undone channel by channel).
// * JPEG has no alpha: the image is flattened onto white first.
// The image is handed over labelled straight or premultiplied accordingly;
// writes are atomic (see image_write.h). PNG is converted straight into the
// rows of the library's own encoder (png_write.h), with no other copy of the
// image; the other formats go through OpenImageIO, loaded when first needed.
#pragma once

#include "casteljau/paint/canvas.h"

#include <string>

namespace casteljau {

/// Writes a Canvas or a Canvas8; an error message, or empty on success.
template <class Pixel>
std::string write_canvas_atomic(const std::string& path, const BasicCanvas<Pixel>& canvas);

} // namespace casteljau
