// Executing a filter graph: inputs resolved and converted to each
// primitive's color space, primitives dispatched to their families'
// files, results freed after their last reader.
//
// Color spaces (Filter Effects 1, 17.7): each primitive converts its inputs
// to its own color-interpolation-filters space and tags its result with
// it; the final result is converted back to sRGB. Primitives that only move
// pixels (feOffset, feTile, feImage) keep their input's space, so a chain of
// them adds no rounding. feDisplacementMap converts only its map (in2) and
// keeps the space of `in` (15.12). SourceAlpha and the transparent
// BackgroundImage are the same in both spaces.
//
// Device mapping of parameters: sx, sy are the lengths of the user axes on
// the device (|M (1, 0)|, |M (0, 1)|); a standard deviation, radius or
// scale along x is multiplied by sx, along y by sy; offsets are mapped as
// vectors; light positions as points, their z by sqrt(sx sy).
#include "casteljau/filter/run.h"

#include "casteljau/filter/blur.h"
#include "casteljau/filter/color_space.h"
#include "casteljau/filter/color_transform.h"
#include "casteljau/filter/compose.h"
#include "casteljau/filter/morphology.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace casteljau {

namespace {

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>; // clang before 17 deduces no aggregate

struct Scales {
    double sx, sy;
    explicit Scales(const Affine& m) : sx(std::hypot(m.a, m.b)), sy(std::hypot(m.c, m.d)) {}
};

// The subregion of `px` (device) within the window `w`, in window coordinates.
Subregion window_part(const PixelRect& px, const PixelRect& w) {
    return {std::clamp(px.x0, w.x0, w.x1) - w.x0, std::clamp(px.y0, w.y0, w.y1) - w.y0,
            std::clamp(px.x1, w.x0, w.x1) - w.x0, std::clamp(px.y1, w.y0, w.y1) - w.y0};
}

// The device shift of a user-space (dx, dy), as the run rounds it: its
// larger coordinate, and a pixel for the rounding. (The length times the
// largest column norm, as it was, falls short under skew: matrix(0.5 1
// -0.5 1 0 0) moves (70.7, 70.7) by 141 rows, which that put at 113.)
double shift_reach(const Affine& m, double dx, double dy) {
    const Vec2 d = m * Vec2{dx, dy};
    return std::max(std::fabs(d.x), std::fabs(d.y)) + 1;
}

// How far one primitive reads from the pixel it writes (device px).
double reach_of(const FilterPrimitive& p, const Scales& s, const Affine& m) {
    constexpr double kFar = std::numeric_limits<double>::infinity();
    const double scale = std::max(s.sx, s.sy);
    return std::visit(
        Overloaded{
            [&](const GaussianBlur& b) {
                if (b.edge != EdgeMode::None) return kFar;
                return double(std::max(blur_reach(b.sx * s.sx), blur_reach(b.sy * s.sy)));
            },
            [&](const Offset& o) { return shift_reach(m, o.dx, o.dy); },
            [&](const Morphology& m) { return std::ceil(std::max(m.rx, m.ry) * scale); },
            [&](const Convolve& c) {
                if (c.m.edge != EdgeMode::None) return kFar;
                return double(std::max(c.m.order_x, c.m.order_y));
            },
            [&](const Displacement& d) { return std::ceil(std::fabs(d.scale) * scale / 2) + 1; },
            [&](const Tile&) { return kFar; },
            [&](const LightingOp&) { return 1.0; },
            [&](const DropShadow& d) {
                return double(std::max(blur_reach(d.sx * s.sx), blur_reach(d.sy * s.sy))) +
                       shift_reach(m, d.dx, d.dy);
            },
            [&](const auto&) { return 0.0; },
        },
        p.op);
}

// The images of one run: the primitives' results and six temporaries (two
// converted inputs, a drop shadow's two, SourceAlpha and a transparent
// image), their storage taken from and
// given back to the pool, so that a renderer's frames allocate none anew
// (a fresh window-sized image is pages the kernel has to fault in).
class Results {
  public:
    Results(std::size_t n, const PixelRect& window, std::vector<FilterImage>* pool)
        : images_(n), window_(window), pool_(pool ? pool : &own_) {
        for (FilterImage& t : temp_) t = take();
    }
    ~Results() {
        for (FilterImage& img : images_)
            if (img.px.capacity()) pool_->push_back(std::move(img));
        for (FilterImage& t : temp_) pool_->push_back(std::move(t));
    }
    Results(const Results&) = delete;
    Results& operator=(const Results&) = delete;

    FilterImage& make(std::size_t i, bool linear) {
        images_[i] = take();
        images_[i].reset(window_, linear);
        return images_[i];
    }
    void free(std::size_t i) {
        pool_->push_back(std::move(images_[i]));
        images_[i] = {};
    }
    FilterImage& operator[](std::size_t i) { return images_[i]; }
    /// Temporary k (0 to 5), any size.
    FilterImage& temp(std::size_t k) { return temp_[k]; }

  private:
    FilterImage take() {
        if (pool_->empty()) return {};
        FilterImage img = std::move(pool_->back());
        pool_->pop_back();
        return img;
    }
    std::vector<FilterImage> images_;
    std::array<FilterImage, 6> temp_;
    PixelRect window_;
    std::vector<FilterImage> own_; // the pool when the caller gives none
    std::vector<FilterImage>* pool_;
};

// A primitive's input `index`, in the space `linear` when `convert`.
class Inputs {
  public:
    Inputs(const FilterSources& io, Results& results)
        : io_(io), results_(results), alpha_(results.temp(4)), empty_(results.temp(5)) {}
    const FilterImage& get(int index, bool linear, bool convert, FilterImage& scratch) {
        const FilterImage* img = find(index, linear);
        if (!convert || img->linear == linear) return *img;
        scratch = *img;
        convert_space(scratch, linear);
        return scratch;
    }

  private:
    const FilterImage* find(int index, bool linear) {
        using namespace filter_input;
        if (index >= 0) return &results_[std::size_t(index)];
        if (index == kSourceGraphic) return io_.source;
        if (index == kSourceAlpha) {
            if (!have_alpha_) {
                have_alpha_ = true;
                alpha_.reset(io_.source->box, linear);
                for (std::size_t i = 0; i < alpha_.px.size(); ++i)
                    alpha_.px[i].a = io_.source->px[i].a;
            }
            alpha_.linear = linear; // alpha alone is the same in both spaces
            return &alpha_;
        }
        const FilterImage* paint = index == kFillPaint     ? io_.fill_paint
                                   : index == kStrokePaint ? io_.stroke_paint
                                                           : nullptr;
        if (paint) return paint;
        if (!have_empty_) empty_.reset(io_.source->box, linear);
        have_empty_ = true;
        empty_.linear = linear;
        return &empty_;
    }
    const FilterSources& io_;
    Results& results_;
    FilterImage &alpha_, &empty_; // made on first use
    bool have_alpha_ = false, have_empty_ = false;
};

} // namespace

PixelRect device_pixels(const Rect& r, const Affine& m) {
    if (r.is_empty()) return {};
    const Rect b = mapped_box(r, m);
    // Bounded so that the pixel coordinates fit an int with room to spare;
    // the renderer cuts the box to the frame anyway.
    static constexpr double kLimit = 1 << 28;
    const auto clampd = [](double v) { return std::clamp(v, -kLimit, kLimit); };
    if (!(b.x0 <= b.x1 && b.y0 <= b.y1)) return {};
    return {int(std::floor(clampd(b.x0))), int(std::floor(clampd(b.y0))),
            int(std::ceil(clampd(b.x1))), int(std::ceil(clampd(b.y1)))};
}

PixelRect filter_pixel_region(const FilterGraph& g, const Affine& to_device) {
    return device_pixels(g.region, to_device);
}

// Along the graph: a result reads its inputs within its own reach, and
// they theirs within theirs, so the filter's result (the last primitive's)
// reaches as far as its longest path of inputs adds up to. (The sum over
// all primitives counted sixteen offsets of the source, merged, sixteen
// times: a window three times the band's height, and its memory.)
double filter_reach(const FilterGraph& g, const Affine& to_device) {
    const Scales s(to_device);
    std::vector<double> reach(g.primitives.size());
    for (std::size_t i = 0; i < g.primitives.size(); ++i) {
        double in = 0;
        for (int k : g.primitives[i].inputs)
            if (k >= 0 && std::size_t(k) < i) in = std::max(in, reach[std::size_t(k)]);
        reach[i] = in + reach_of(g.primitives[i], s, to_device);
    }
    return reach.empty() ? 0.0 : reach.back();
}

namespace {

// A shift of v device px in whole pixels (rounded), bounded beyond any
// window (everything moves out), 0 for NaN.
int whole_pixels(double v) {
    constexpr double kFar = 1 << 28;
    return v == v ? int(std::lround(std::clamp(v, -kFar, kFar))) : 0;
}

/// The largest morphology radius (device px): the erosion and dilation
/// cost grows with it, and beyond it a layer is eroded away or flooded.
constexpr double kMaxMorphologyRadius = 256;

// One primitive run: its inputs, its output, its subregion.
struct Step {
    const FilterPrimitive& p;
    const Affine& m;
    const Scales& s;
    const FilterSources& io;
    Inputs& inputs;
    FilterImage& out;
    Subregion sub;
    Results& results;

    int input_index(std::size_t k) const {
        return k < p.inputs.size() ? p.inputs[k] : filter_input::kSourceGraphic;
    }
    // Input k in the primitive's space, or as it is when !convert.
    const FilterImage& in(std::size_t k, bool convert = true) {
        return inputs.get(input_index(k), p.linear, convert,
                          results.temp(std::min<std::size_t>(k, 1)));
    }
    // Copies `src` into out over the subregion, keeping src's space.
    void copy(const FilterImage& src) {
        out.linear = src.linear;
        for (int y = sub.y0; y < sub.y1; ++y)
            for (int x = sub.x0; x < sub.x1; ++x) out.at(x, y) = src.at(x, y);
    }

    void operator()(const GaussianBlur& b) {
        const double sx = std::max(0.0, b.sx) * s.sx, sy = std::max(0.0, b.sy) * s.sy;
        const FilterImage& src = in(0);
        if (!(sx > 0) && !(sy > 0)) return copy(src); // 15.15: disabled, the input itself
        const bool alpha_only = input_index(0) == filter_input::kSourceAlpha;
        gaussian_blur(src, out, sub, sx, sy, b.edge, alpha_only);
    }
    void operator()(const Offset& o) {
        const Vec2 d = m * Vec2{o.dx, o.dy};
        const FilterImage& src = in(0, false);
        out.linear = src.linear;
        offset(src, out, sub, whole_pixels(d.x), whole_pixels(d.y));
    }
    void operator()(const Flood& f) { flood(out, sub, color_in_space(f.color, p.linear)); }
    void operator()(const Blend& b) { blend(in(0), in(1), out, sub, b.mode); }
    void operator()(const Composite& c) { composite(in(0), in(1), out, sub, c); }
    void operator()(const Merge&) {
        for (std::size_t k = 0; k < p.inputs.size(); ++k) {
            const FilterImage* img = &inputs.get(p.inputs[k], p.linear, true, results.temp(0));
            merge({&img, 1}, out, sub);
        }
    }
    void operator()(const ColorMatrix& c) { color_matrix(in(0), out, sub, c); }
    void operator()(const ComponentTransfer& t) { component_transfer(in(0), out, sub, t); }
    void operator()(const Morphology& mo) {
        const FilterImage& src = in(0);
        // 15.20: a radius of zero or less disables the primitive (the input itself).
        if (!(mo.rx > 0 && mo.ry > 0)) return copy(src);
        const auto px = [](double r) { return whole_pixels(std::min(r, kMaxMorphologyRadius)); };
        morphology(src, out, sub, mo.dilate, px(mo.rx * s.sx), px(mo.ry * s.sy));
    }
    void operator()(const Convolve& c) { convolve(in(0), out, sub, c.m); }
    void operator()(const TurbulenceOp& t) { turbulence(out, sub, t.t, m.inverse(), p.subregion); }
    void operator()(const Displacement& d) {
        const FilterImage& src = in(0, false);
        const FilterImage& map = in(1);
        out.linear = src.linear;
        displacement_map(src, map, out, sub, d.scale * s.sx, d.scale * s.sy, d.x, d.y);
    }
    void operator()(const Tile&) {} // needs the input's subregion: run_filter does it
    void operator()(const ImageInput& i) {
        if (i.index >= 0 && std::size_t(i.index) < io.images.size())
            copy(io.images[std::size_t(i.index)]);
        else
            out.linear = false;
    }
    void operator()(const LightingOp& op) {
        Lighting l = op.l;
        const auto encode = [&](float v) { return p.linear ? srgb_to_linear(v) : v; };
        l.color = {encode(op.l.color.r), encode(op.l.color.g), encode(op.l.color.b), 1};
        const double sz = std::sqrt(s.sx * s.sy);
        const auto place = [&](double& x, double& y, double& z) {
            const Point q = m * Point{x, y};
            x = q.x;
            y = q.y;
            z *= sz;
        };
        if (auto* pl = std::get_if<PointLight>(&l.light)) place(pl->x, pl->y, pl->z);
        if (auto* sl = std::get_if<SpotLight>(&l.light)) {
            place(sl->x, sl->y, sl->z);
            place(sl->at_x, sl->at_y, sl->at_z);
        }
        lighting(in(0), out, sub, l);
    }
    void operator()(const DropShadow& d) {
        const FilterImage& src = in(0);
        FilterImage &alpha = results.temp(2), &blurred = results.temp(3);
        alpha.reset(src.box, p.linear);
        for (std::size_t i = 0; i < src.px.size(); ++i) alpha.px[i].a = src.px[i].a;
        blurred.reset(src.box, p.linear);
        const Subregion all{0, 0, src.width(), src.height()};
        const double sx = std::max(0.0, d.sx) * s.sx, sy = std::max(0.0, d.sy) * s.sy;
        const FilterImage* shadow = &alpha;
        if (sx > 0 || sy > 0) {
            gaussian_blur(alpha, blurred, all, sx, sy, EdgeMode::None, true);
            shadow = &blurred;
        }
        const Vec2 v = m * Vec2{d.dx, d.dy};
        const int dx = whole_pixels(v.x), dy = whole_pixels(v.y);
        const Premul c = color_in_space(d.color, p.linear);
        for (int y = sub.y0; y < sub.y1; ++y)
            for (int x = sub.x0; x < sub.x1; ++x) {
                const float k = shadow->get(x - dx, y - dy).a;
                const Premul& f = src.at(x, y);
                const float under = k * (1 - f.a);
                out.at(x, y) = {f.r + c.r * under, f.g + c.g * under, f.b + c.b * under,
                                f.a + c.a * under};
            }
    }
};

// Under a rotation or skew the filter region and the subregions are
// parallelograms on the device, not their bounding boxes: clears the
// pixels of `sub` whose centres map outside `user` (the rectangle in user
// space; `to_user` maps device to user space).
void cut_to(FilterImage& img, const Subregion& sub, const Rect& user, const Affine& to_user) {
    for (int y = sub.y0; y < sub.y1; ++y)
        for (int x = sub.x0; x < sub.x1; ++x) {
            const Point q = to_user * Point{img.box.x0 + x + 0.5, img.box.y0 + y + 0.5};
            if (!user.contains(q)) img.at(x, y) = {};
        }
}

// The last primitive reading each result (its own index when none does).
std::vector<std::size_t> last_uses(const FilterGraph& g) {
    std::vector<std::size_t> last(g.primitives.size());
    for (std::size_t i = 0; i < last.size(); ++i) {
        last[i] = i;
        for (int k : g.primitives[i].inputs)
            if (k >= 0) last[std::size_t(k)] = i;
    }
    return last;
}

// The run's temporaries (Results::temp): two converted inputs, a drop
// shadow's two, SourceAlpha and a transparent image.
constexpr std::size_t kTemporaries = 6;
// Whether primitive i reads result k last, and so frees it: once, should it
// list k twice (marked in `last`, last_uses').
bool frees(std::vector<std::size_t>& last, int k, std::size_t i) {
    if (k < 0 || last[std::size_t(k)] != i) return false;
    last[std::size_t(k)] = std::size_t(-1);
    return true;
}

bool valid(const FilterGraph& g) {
    if (g.primitives.empty() || g.primitives.size() > kMaxFilterPrimitives) return false;
    for (std::size_t i = 0; i < g.primitives.size(); ++i)
        for (int k : g.primitives[i].inputs)
            if (k >= int(i) || k < filter_input::kStrokePaint) return false;
    return true;
}

} // namespace

std::size_t filter_held_images(const FilterGraph& g) {
    if (!valid(g)) return kTemporaries; // the run fails before it makes any result
    // The run's own count: a result is made, and freed after the primitive
    // that reads it last.
    std::vector<std::size_t> last = last_uses(g);
    std::size_t live = 0, most = 0;
    for (std::size_t i = 0; i < g.primitives.size(); ++i) {
        most = std::max(most, ++live);
        for (int k : g.primitives[i].inputs)
            if (frees(last, k, i)) --live;
    }
    return most + kTemporaries;
}

bool run_filter(const FilterGraph& g, const Affine& to_device, const FilterSources& io) {
    FilterImage& source = *io.source;
    const PixelRect window = source.box;
    const std::size_t bytes = source.px.size() * sizeof(Premul);
    if (!valid(g) || (bytes > 0 && filter_held_images(g) > kMaxFilterBytes / bytes)) {
        source.reset(window, false);
        return false;
    }
    const Scales scales(to_device);
    const PixelRect region = filter_pixel_region(g, to_device);
    const bool axis_aligned = to_device.b == 0 && to_device.c == 0;
    const Affine to_user = to_device.inverse();
    if (!axis_aligned) // the source too: nothing outside the region is read
        cut_to(source, {0, 0, source.width(), source.height()}, g.region, to_user);
    std::vector<std::size_t> last = last_uses(g);
    Results results(g.primitives.size(), window, io.pool);
    Inputs inputs(io, results);
    std::size_t live = 0;
    for (std::size_t i = 0; i < g.primitives.size(); ++i) {
        const FilterPrimitive& p = g.primitives[i];
        if (++live * bytes > kMaxFilterBytes) {
            source.reset(window, false);
            return false;
        }
        const Rect user_sub = p.subregion.intersected(g.region);
        const PixelRect cut = device_pixels(user_sub, to_device).intersected(region);
        Step step{p,
                  to_device,
                  scales,
                  io,
                  inputs,
                  results.make(i, p.linear),
                  window_part(cut, window),
                  results};
        if (std::holds_alternative<Tile>(p.op)) {
            const FilterImage& src = step.in(0, false);
            const int k = step.input_index(0);
            const PixelRect t =
                k >= 0 ? device_pixels(g.primitives[std::size_t(k)].subregion.intersected(g.region),
                                       to_device)
                       : region;
            step.out.linear = src.linear;
            tile(src, {t.x0 - window.x0, t.y0 - window.y0, t.x1 - window.x0, t.y1 - window.y0},
                 step.out, step.sub);
        } else if (!step.sub.empty()) {
            std::visit(step, p.op);
        }
        if (!axis_aligned) cut_to(step.out, step.sub, user_sub, to_user);
        for (int k : p.inputs)
            if (frees(last, k, i)) {
                results.free(std::size_t(k));
                --live;
            }
    }
    FilterImage& result = results[g.primitives.size() - 1];
    convert_space(result, false);
    std::swap(source, result); // the source's storage goes back to the pool
    return true;
}

} // namespace casteljau
