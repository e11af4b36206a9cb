// A filter: a graph of primitives in the filtered element's user space
// (Filter Effects 1, 8 and 9), resolved by a reader (svg/filters.cpp, or the
// CSS filter functions) into what filter/run.h executes.
//
// Resolved means: every length is in user units (primitiveUnits and
// filterUnits applied), every subregion is explicit (the spec's defaults
// applied: 0%/100% of the filter region, or the union of the inputs'
// subregions), every `in` names its input by index (an earlier primitive's
// result, or one of the standard inputs below; an unnamed or unknown `in`
// is the previous result, or SourceGraphic for the first primitive), and
// each primitive knows the color space it works in. Colors are straight
// sRGB, as CSS gives them; the run converts them into the primitive's space.
#pragma once

#include "casteljau/filter/convolve.h"
#include "casteljau/filter/displacement.h"
#include "casteljau/filter/filter_image.h"
#include "casteljau/filter/lighting.h"
#include "casteljau/filter/turbulence.h"
#include "casteljau/geom/rect.h"
#include "casteljau/paint/blend.h"
#include "casteljau/paint/color.h"

#include <array>
#include <variant>
#include <vector>

namespace casteljau {

/// The standard inputs, as negative input indices (a primitive's own
/// result is its index, 0 and up). BackgroundImage and BackgroundAlpha
/// are transparent black, as in resvg and every browser but old IE.
namespace filter_input {
inline constexpr int kSourceGraphic = -1;
inline constexpr int kSourceAlpha = -2;
inline constexpr int kBackgroundImage = -3;
inline constexpr int kBackgroundAlpha = -4;
inline constexpr int kFillPaint = -5;
inline constexpr int kStrokePaint = -6;
} // namespace filter_input

/// feGaussianBlur, and the CSS blur(): standard deviations in user units.
struct GaussianBlur {
    double sx = 0, sy = 0;
    EdgeMode edge = EdgeMode::None;
};
/// feOffset: a shift in user units.
struct Offset {
    double dx = 0, dy = 0;
};
/// feFlood: flood-color with flood-opacity folded into its alpha.
struct Flood {
    Rgba color;
};
/// feBlend: in over in2, blended with `mode`.
struct Blend {
    BlendMode mode = BlendMode::Normal;
};
/// feComposite: a Porter-Duff operator of in over in2, or arithmetic.
struct Composite {
    /// The operator attribute's values.
    enum class Op : unsigned char { Over, In, Out, Atop, Xor, Lighter, Arithmetic };
    Op op = Op::Over;
    float k1 = 0, k2 = 0, k3 = 0, k4 = 0; ///< arithmetic only
};
/// feMerge: its inputs, each over the ones before.
struct Merge {};
/// feColorMatrix, every type as its 5 x 4 matrix (row-major: R' = m[0] R
/// + m[1] G + m[2] B + m[3] A + m[4]), on straight colors.
struct ColorMatrix {
    std::array<float, 20> m{1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0};
};
/// One channel's function of feComponentTransfer.
struct TransferFunction {
    /// The type attribute's values.
    enum class Type : unsigned char { Identity, Table, Discrete, Linear, Gamma };
    Type type = Type::Identity;
    std::vector<float> table;
    float slope = 1, intercept = 0, amplitude = 1, exponent = 1, offset = 0;
};
/// feComponentTransfer: a function per channel, R, G, B, A, on straight colors.
struct ComponentTransfer {
    std::array<TransferFunction, 4> f;
};
/// feMorphology: radii in user units.
struct Morphology {
    bool dilate = false;
    double rx = 0, ry = 0;
};
/// feConvolveMatrix: the kernel applies per device pixel (kernelUnitLength
/// is ignored, as resvg and Chrome at scale 1 do).
struct Convolve {
    ConvolveMatrix m;
};
/// feTurbulence: frequencies per user unit.
struct TurbulenceOp {
    Turbulence t;
};
/// feDisplacementMap: in displaced by in2, scale in user units.
struct Displacement {
    double scale = 0;
    Channel x = Channel::A, y = Channel::A;
};
/// feTile: in's subregion repeated over this primitive's subregion.
struct Tile {};
/// feImage: a drawing the renderer makes (Filter::images[index]).
struct ImageInput {
    int index = 0;
};
/// feDiffuseLighting / feSpecularLighting with the light in user space.
struct LightingOp {
    Lighting l; ///< positions in user units; color straight sRGB
};
/// feDropShadow: in's alpha blurred, offset and flooded, under in.
struct DropShadow {
    double sx = 0, sy = 0, dx = 0, dy = 0;
    Rgba color;
};

using FilterOp = std::variant<GaussianBlur, Offset, Flood, Blend, Composite, Merge, ColorMatrix,
                              ComponentTransfer, Morphology, Convolve, TurbulenceOp, Displacement,
                              Tile, ImageInput, LightingOp, DropShadow>;

/// One primitive: what it does, what it reads, where it writes, in what space.
struct FilterPrimitive {
    FilterOp op;
    std::vector<int> inputs; ///< in, in2 (or feMerge's nodes): indices as above
    Rect subregion;          ///< user space, cut to the filter region by the run
    bool linear = true;      ///< color-interpolation-filters: linearRGB (initial), else sRGB
};

/// A filter: its region and its primitives, in user space.
struct FilterGraph {
    Rect region; ///< user space; nothing outside it is drawn
    std::vector<FilterPrimitive> primitives;
};

} // namespace casteljau
