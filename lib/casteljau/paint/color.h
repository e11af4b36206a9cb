// Colors. `Rgba` is straight (not premultiplied) sRGB-encoded color in [0, 1],
// as SVG and CSS specify colors; `Premul` is the premultiplied form the
// compositor works in. Compositing happens in sRGB-encoded space, as SVG 1.1
// renderers do (color-interpolation: sRGB).
#pragma once

namespace casteljau {

/// A straight (not premultiplied) sRGB color with alpha, components in [0, 1].
struct Rgba {
    float r = 0, g = 0, b = 0, a = 1;
    /// Exact equality of every member.
    constexpr bool operator==(const Rgba&) const = default;
};

/// A premultiplied color: what the compositor works in.
struct Premul {
    float r = 0, g = 0, b = 0, a = 0;
};

constexpr Premul premultiply(Rgba c, float opacity = 1.0f) {
    const float a = c.a * opacity;
    return {c.r * a, c.g * a, c.b * a, a};
}

} // namespace casteljau
