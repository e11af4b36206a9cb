// Fuzz target: a filter graph decoded from the bytes (any primitives, any
// parameters, inputs that point anywhere: forward, at themselves, at no
// primitive) run on a small window, under a random transform. What
// run_filter accepts must run in bounded time and memory; what it refuses
// (cycles, missing inputs) must be refused, never crash.
#include "casteljau/filter/run.h"
#include "fuzz_input.h"
#include "fuzz_target.h"

#include <cmath>
#include <cstring>

namespace {

using namespace casteljau;

using fuzz::Bytes;

// An input index: -6 .. i + 2, the standard inputs, earlier results and later ones.
int input(Bytes& b, int i) { return int(b.byte() % (i + 9)) - 6; }

FilterOp op(Bytes& b) {
    switch (b.byte() % 16) {
    case 0:
        return GaussianBlur{b.number(), b.number(), EdgeMode(b.byte() % 3)};
    case 1:
        return Offset{b.number(), b.number()};
    case 2:
        return Flood{{float(b.byte()) / 255, 0.5f, 0.25f, float(b.byte()) / 255}};
    case 3:
        return Blend{BlendMode(b.byte() % 16)};
    case 4:
        return Composite{Composite::Op(b.byte() % 7), float(b.number()), float(b.number()),
                         float(b.number()), float(b.number())};
    case 5:
        return Merge{};
    case 6: {
        ColorMatrix m;
        for (float& v : m.m) v = float(b.number());
        return m;
    }
    case 7: {
        ComponentTransfer t;
        for (TransferFunction& f : t.f) {
            f.type = TransferFunction::Type(b.byte() % 5);
            for (int i = b.byte() % 6; i > 0; --i) f.table.push_back(float(b.number()));
            f.slope = float(b.number()), f.exponent = float(b.number());
        }
        return t;
    }
    case 8:
        return Morphology{bool(b.byte() & 1), b.number(), b.number()};
    case 9: {
        Convolve c;
        c.m.order_x = 1 + b.byte() % 5, c.m.order_y = 1 + b.byte() % 5;
        for (int i = 0; i < c.m.order_x * c.m.order_y; ++i) c.m.kernel.push_back(float(b.number()));
        c.m.divisor = float(b.number());
        c.m.target_x = b.byte() % c.m.order_x, c.m.target_y = b.byte() % c.m.order_y;
        c.m.edge = EdgeMode(b.byte() % 3);
        c.m.preserve_alpha = b.byte() & 1;
        if (c.m.divisor == 0) c.m.divisor = 1; // the reader's guarantee
        return c;
    }
    case 10: {
        Turbulence t;
        t.base_x = std::fabs(b.number()), t.base_y = std::fabs(b.number());
        t.octaves = b.byte() % 6, t.seed = b.number();
        t.fractal_noise = b.byte() & 1, t.stitch = b.byte() & 1;
        return TurbulenceOp{t};
    }
    case 11:
        return Displacement{b.number(), Channel(b.byte() % 4), Channel(b.byte() % 4)};
    case 12:
        return Tile{};
    case 13:
        return ImageInput{b.byte() % 3 - 1};
    case 14: {
        Lighting l;
        l.specular = b.byte() & 1;
        l.surface_scale = b.number(), l.constant = b.number();
        l.specular_exponent = 1 + b.byte() % 128;
        l.color = {1, 0.5f, 0.25f, 1};
        if (b.byte() & 1)
            l.light = PointLight{b.number(), b.number(), b.number()};
        else
            l.light = SpotLight{b.number(), b.number(), b.number(), b.number(),
                                b.number(), b.number(), b.number(), b.number()};
        return LightingOp{l};
    }
    default:
        return DropShadow{b.number(), b.number(), b.number(), b.number(), {0, 0, 0, 1}};
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Bytes b{data, size};
    FilterGraph g;
    g.region = Rect::from_points({b.number(), b.number()}, {b.number(), b.number()});
    const Affine m{b.number() / 10, b.number() / 100, b.number() / 100,
                   b.number() / 10, b.number(),       b.number()};
    if (!std::isfinite(m.determinant()) || m.determinant() == 0)
        return 0; // the renderer's guarantee
    const int count = b.byte() % 12;
    for (int i = 0; i < count; ++i) {
        FilterPrimitive p{op(b), {}, g.region, bool(b.byte() & 1)};
        for (int k = b.byte() % 4; k > 0; --k) p.inputs.push_back(input(b, i));
        p.subregion = Rect::from_points({b.number(), b.number()}, {b.number(), b.number()});
        g.primitives.push_back(std::move(p));
    }
    FilterImage source;
    source.reset({-3, 5, 29, 29}, false);
    for (Premul& p : source.px) {
        const float a = float(b.byte()) / 255;
        p = {a * 0.5f, a * 0.25f, a, a};
    }
    FilterImage image = source;
    (void)filter_reach(g, m);
    run_filter(g, m, {&source, {&image, 1}, &image, nullptr});
    return 0;
}
