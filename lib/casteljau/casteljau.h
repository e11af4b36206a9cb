// The public API in one include, for applications: paths and curves, the
// drawing and its renderers, hit-testing, editing, and image output. Each
// header can also be included on its own.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/curve/path_data.h"
#include "casteljau/edit/bezier_spline.h"
#include "casteljau/edit/interpolate.h"
#include "casteljau/hit/nearest.h"
#include "casteljau/hit/rect_hit.h"
#include "casteljau/hit/stroke_hit.h"
#include "casteljau/hit/winding.h"
#include "casteljau/io/canvas_write.h"
#include "casteljau/paint/straight_rgba.h"
#include "casteljau/render/drawing.h"
#include "casteljau/render/output_size.h"
