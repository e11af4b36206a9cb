// Glyph outlines (text/font.h) against FreeType, which reads the same files:
// the outlines are the font's own segments and contours, exactly; they
// flatten within the tolerance like every other curve; and drawn through
// Casteljau's rasterizer they cover what FreeType's gray rasterizer covers.
// That rasterizer computes exact areas too, but of a polyline it makes
// coarsely (1/16 px for a quadratic, ~1/6 px for a cubic), which at text
// sizes is off the true coverage by 1 to 5/255 on average: the reference is
// FreeType at ~1100 px, box-filtered down, where that error is negligible.
// The fonts are the Debian packages the tests pin (fonts-dejavu-core for
// TrueType quadratics, fonts-noto-cjk for CFF cubics), never whatever the
// machine happens to have.
#include "casteljau/flatten/path_flatten.h"
#include "casteljau/raster/path_edges.h"
#include "casteljau/raster/rasterizer.h"
#include "casteljau/text/font.h"
#include "casteljau/text/utf8.h"
#include "coverage.h"
#include "text_test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ft2build.h>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>
#include <vector>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

namespace casteljau {
namespace {

using text_test::control_point_distance;
using text_test::control_points;

const std::string kDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
// A collection of CFF-flavoured OpenType faces; face 0 is Noto Sans CJK JP.
const std::string kNotoSansCjk = "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc";

// The glyphs compared: round and straight stems, counters, crossings
// (@, &, 8), accents and a stroke through a letter, and for the CJK face
// dense ideographs whose strokes are a pixel wide at small sizes.
const char* const kLatinSample = "AgQ@%&8\xC3\x9F\xC3\xA9\xC5\x81Ws$y";
const char* const kCjkSample = "AgQ@&8\xE6\xB0\xB8\xE8\xAA\x9E\xE9\xAC\xB1\xE3\x81\x82";

// FreeType's library and one face, for the reference renderings.
class FtFace {
  public:
    FtFace(const std::string& file, int index) {
        if (FT_Init_FreeType(&library_) == 0) FT_New_Face(library_, file.c_str(), index, &face_);
    }
    ~FtFace() {
        if (face_) FT_Done_Face(face_);
        if (library_) FT_Done_FreeType(library_);
    }
    FtFace(const FtFace&) = delete;
    FtFace& operator=(const FtFace&) = delete;
    FT_Face get() const { return face_; }

  private:
    FT_Library library_ = nullptr;
    FT_Face face_ = nullptr;
};

// A glyph's coverage, each pixel's in [0, 1], on a frame of whole pixels of
// the glyph's pixel space (y up): pixel (0, 0) has its top left corner at
// (left, top).
struct Coverage {
    int width = 0, height = 0, left = 0, top = 0;
    std::vector<double> c;
    double& at(int x, int y) { return c[std::size_t(y * width + x)]; }
};

// A frame holding the outline at `scale` px per font unit, with a pixel to
// spare on every side.
Coverage frame_of(const Path& outline, double scale) {
    const Rect b = outline.control_bounds();
    Coverage f;
    f.left = int(std::floor(b.x0 * scale)) - 1;
    f.top = int(std::ceil(b.y1 * scale)) + 1;
    f.width = int(std::ceil(b.x1 * scale)) + 1 - f.left;
    f.height = f.top - (int(std::floor(b.y0 * scale)) - 1);
    f.c.assign(std::size_t(f.width * f.height), 0.0);
    return f;
}

// Floor division, for pixel indices of either sign.
int floor_div(int a, int b) { return int(std::floor(double(a) / b)); }

// FreeType's unhinted rendering at `px` px, of 8-bit levels v taken as v / 255
// (full pixels are 255), added into `frame` box-filtered by `k`: each of its
// pixels is k x k pixels of the rendering. Returns FreeType's px per font
// unit (FT_Set_Pixel_Sizes keeps it as a 16.16 fraction of 26.6 units, a
// little off px / units_per_em; the comparison is of rasterizers, not of
// that rounding), 0 when the glyph does not render. `outside` gets the
// coverage that falls outside the frame.
double add_freetype(FT_Face face, std::uint32_t glyph, int px, int k, Coverage& frame,
                    double& outside) {
    if (FT_Set_Pixel_Sizes(face, 0, FT_UInt(px)) != 0 ||
        FT_Load_Glyph(face, glyph, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0 ||
        FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL) != 0)
        return 0;
    const FT_Bitmap& bm = face->glyph->bitmap;
    const int left = face->glyph->bitmap_left, top = face->glyph->bitmap_top;
    const double weight = 1.0 / (255.0 * k * k);
    outside = 0;
    for (int y = 0; y < int(bm.rows); ++y) {
        const unsigned char* row = bm.pitch >= 0 ? bm.buffer + y * bm.pitch
                                                 : bm.buffer + (y - int(bm.rows) + 1) * bm.pitch;
        // The pixel's bottom edge, y up, in the rendering's pixels, and the
        // frame's row holding it.
        const int fy = frame.top - 1 - floor_div(top - y - 1, k);
        for (int x = 0; x < int(bm.width); ++x) {
            if (row[x] == 0) continue;
            const int fx = floor_div(left + x, k) - frame.left;
            if (fx < 0 || fy < 0 || fx >= frame.width || fy >= frame.height)
                outside += row[x] * weight;
            else
                frame.at(fx, fy) += row[x] * weight;
        }
    }
    return double(face->size->metrics.x_scale) / (65536.0 * 64.0);
}

// The outline through Casteljau's own pipeline (curve culling, flattening at
// `tolerance`, exact-area accumulation) into a frame like `like`.
Coverage casteljau_render(const Path& outline, double scale, const Coverage& like,
                          double tolerance) {
    Coverage f = like;
    EdgeList edges;
    edges.reset(f.width, f.height);
    const Affine to_device{scale, 0, 0, -scale, -double(f.left), double(f.top)};
    add_path_edges(outline, to_device, {tolerance}, edges);
    testing::CoverageImage img(f.width, f.height);
    Rasterizer().fill(edges, FillRule::NonZero, true, img);
    EXPECT_TRUE(img.order_ok());
    for (std::size_t i = 0; i < f.c.size(); ++i) f.c[i] = img.data()[i];
    return f;
}

// Sum over the pixels of |a - b|: an area, px^2.
double abs_difference(const Coverage& a, const Coverage& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.c.size(); ++i) d += std::fabs(a.c[i] - b.c[i]);
    return d;
}
double max_difference(const Coverage& a, const Coverage& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.c.size(); ++i) d = std::max(d, std::fabs(a.c[i] - b.c[i]));
    return d;
}
// Mean |a - b| over the frame, in levels of 1/255.
double mean_levels(const Coverage& a, const Coverage& b) {
    return abs_difference(a, b) / double(a.c.size()) * 255;
}

// The outline's length at `scale`, px, to 1e-4 px per chord.
double length_px(const Path& outline, double scale) {
    std::vector<Polyline> lines;
    flatten_path(outline, Affine::scale(scale), {1e-4}, lines);
    double l = 0;
    for (const Polyline& pl : lines)
        for (std::size_t i = 1; i < pl.points.size(); ++i)
            l += distance(pl.points[i - 1], pl.points[i]);
    return l;
}

bool has_file(const std::string& f) { return std::filesystem::exists(f); }

// The glyphs of a UTF-8 sample, each a real glyph of the font.
std::vector<std::uint32_t> glyphs_of(const Font& font, const char* sample) {
    std::vector<std::uint32_t> out;
    for (const char32_t c : decode_utf8(sample)) {
        const std::uint32_t g = font.glyph_index(c);
        EXPECT_NE(g, 0u) << "U+" << std::hex << unsigned(c) << " missing from " << font.family();
        if (g != 0) out.push_back(g);
    }
    return out;
}

// The reference: FreeType's gray rasterizer computes exact areas of the
// polyline it makes of each curve, but makes it coarsely (a quadratic to
// 1/16 px in each coordinate, a cubic to about 1/6 px), so at 12 px its
// bitmap is off the true coverage by ~5/255 on average, 8/255 for CFF. At
// ~1100 px and box-filtered down, that error shrinks by the same factor;
// what is left is FreeType's 8-bit quantisation, averaged away.
constexpr int kReferencePx = 1152;

// Every glyph of the sample at every size: Casteljau with a tolerance small
// enough not to matter (0.01 px) against the reference, mean difference
// under one level; at the default 0.25 px, the coverage it loses or gains
// is an area within the tolerance times the outline's length (the region
// between a curve and a chord within e of it is at most e wide). Prints,
// per size, the worst figures and, for comparison, FreeType's own bitmap.
void compare_with_freetype(const std::string& file, int index, const char* sample) {
    std::string error;
    const auto font = Font::load(file, index, {}, &error);
    ASSERT_TRUE(font) << error;
    FtFace ft(file, index);
    ASSERT_TRUE(ft.get()) << file;
    const std::vector<std::uint32_t> glyphs = glyphs_of(*font, sample);
    std::printf("  %s, mean |diff| / max |diff| vs FreeType at %d px box-filtered, in 1/255:\n",
                font->family().c_str(), kReferencePx);
    for (const int px : {8, 12, 16, 24, 36, 48, 72}) {
        const int k = (kReferencePx + px - 1) / px;
        double fine_mean = 0, fine_max = 0, coarse_mean = 0, coarse_max = 0, ft_mean = 0,
               coarse_vs_ft = 0, ratio = 0;
        for (const std::uint32_t g : glyphs) {
            const Path& outline = font->outline(g);
            Coverage ref = frame_of(outline, double(px) / font->metrics().units_per_em);
            double outside = 0;
            const double scale = add_freetype(ft.get(), g, px * k, k, ref, outside) / k;
            ASSERT_GT(scale, 0) << "glyph " << g;
            EXPECT_LT(outside, 1e-3) << "glyph " << g << " at " << px << " px: frame too small";
            Coverage plain = ref;
            std::fill(plain.c.begin(), plain.c.end(), 0.0);
            add_freetype(ft.get(), g, px, 1, plain, outside);

            const Coverage fine = casteljau_render(outline, scale, ref, 0.01);
            const double mean = mean_levels(fine, ref), max = max_difference(fine, ref) * 255;
            EXPECT_LT(mean, 1.0) << font->family() << " glyph " << g << " at " << px
                                 << " px: mean |diff| " << mean << "/255, max " << max << "/255";
            const Coverage coarse = casteljau_render(outline, scale, ref, 0.25);
            const double bound = 0.25 * length_px(outline, scale);
            EXPECT_LE(abs_difference(coarse, ref), bound + abs_difference(fine, ref))
                << font->family() << " glyph " << g << " at " << px << " px";
            fine_mean = std::max(fine_mean, mean);
            fine_max = std::max(fine_max, max);
            coarse_mean = std::max(coarse_mean, mean_levels(coarse, ref));
            coarse_max = std::max(coarse_max, max_difference(coarse, ref) * 255);
            ft_mean = std::max(ft_mean, mean_levels(plain, ref));
            coarse_vs_ft = std::max(coarse_vs_ft, mean_levels(coarse, plain));
            ratio = std::max(ratio, abs_difference(coarse, ref) / bound);
        }
        std::printf("  %2d px: tol 0.01 %.2f / %.1f; tol 0.25 %.2f / %.1f (area %.2f of the "
                    "bound); FreeType 1x %.2f; tol 0.25 vs FreeType 1x %.2f\n",
                    px, fine_mean, fine_max, coarse_mean, coarse_max, ratio, ft_mean, coarse_vs_ft);
    }
}

TEST(GlyphRaster, TrueTypeGlyphsCoverWhatFreeTypeCovers) {
    compare_with_freetype(kDejaVuSans, 0, kLatinSample);
}

TEST(GlyphRaster, CffGlyphsCoverWhatFreeTypeCovers) {
    if (!has_file(kNotoSansCjk)) GTEST_SKIP() << kNotoSansCjk << " (fonts-noto-cjk) missing";
    compare_with_freetype(kNotoSansCjk, 0, kCjkSample);
}

// At display sizes a misplaced control point shows pixel by pixel. At
// 600 px against FreeType at 2400 px box-filtered (whose flattening error,
// 1/16 px for a quadratic and about 1/6 px for a cubic at that size, is then
// a quarter of that), every pixel is within a few levels; a curve off by
// 0.1 px is off by some 25 levels on the pixels it crosses.
void compare_large(const std::string& file, int index, const char* sample) {
    const auto font = Font::load(file, index, {});
    ASSERT_TRUE(font);
    FtFace ft(file, index);
    ASSERT_TRUE(ft.get());
    const int px = 600, k = 4;
    double worst = 0, worst_mean = 0;
    for (const std::uint32_t g : glyphs_of(*font, sample)) {
        Coverage ref = frame_of(font->outline(g), double(px) / font->metrics().units_per_em);
        double outside = 0;
        const double scale = add_freetype(ft.get(), g, px * k, k, ref, outside) / k;
        ASSERT_GT(scale, 0);
        const Coverage ours = casteljau_render(font->outline(g), scale, ref, 0.01);
        const double max = max_difference(ours, ref) * 255;
        EXPECT_LE(max, 20) << font->family() << " glyph " << g << " at " << px << " px: max |diff| "
                           << max << "/255";
        worst = std::max(worst, max);
        worst_mean = std::max(worst_mean, mean_levels(ours, ref));
    }
    std::printf("  %s %d px vs FreeType at %d px box-filtered: worst mean |diff| %.3f/255, "
                "max %.1f/255\n",
                font->family().c_str(), px, px * k, worst_mean, worst);
}

TEST(GlyphRaster, LargeTrueTypeGlyphsMatchFreeTypePixelForPixel) {
    compare_large(kDejaVuSans, 0, kLatinSample);
}

TEST(GlyphRaster, LargeCffGlyphsMatchFreeTypePixelForPixel) {
    if (!has_file(kNotoSansCjk)) GTEST_SKIP() << kNotoSansCjk << " (fonts-noto-cjk) missing";
    compare_large(kNotoSansCjk, 0, kCjkSample);
}

// The comparison can fail: the outline a quarter pixel off, or flattened
// far too coarsely, is more than a level off the reference on average.
TEST(GlyphRaster, TheComparisonSeesAQuarterPixelShiftAndCoarseFlattening) {
    const auto font = Font::load(kDejaVuSans, 0, {});
    ASSERT_TRUE(font);
    FtFace ft(kDejaVuSans, 0);
    ASSERT_TRUE(ft.get());
    const std::uint32_t g = font->glyph_index(U'Q');
    const int px = 48, k = 24;
    Coverage ref = frame_of(font->outline(g), double(px) / font->metrics().units_per_em);
    double outside = 0;
    const double scale = add_freetype(ft.get(), g, px * k, k, ref, outside) / k;
    EXPECT_LT(mean_levels(casteljau_render(font->outline(g), scale, ref, 0.01), ref), 1.0);
    Path moved = font->outline(g);
    moved.transform(Affine::translate({0.25 / scale, 0}));
    EXPECT_GT(mean_levels(casteljau_render(moved, scale, ref, 0.01), ref), 1.0);
    EXPECT_GT(mean_levels(casteljau_render(font->outline(g), scale, ref, 8.0), ref), 1.0);
    // The area bound too: the default tolerance's rendering is not within a
    // fifth of it.
    const Coverage fine = casteljau_render(font->outline(g), scale, ref, 0.01);
    const Coverage coarse = casteljau_render(font->outline(g), scale, ref, 0.25);
    EXPECT_GT(abs_difference(coarse, ref),
              0.05 * length_px(font->outline(g), scale) + abs_difference(fine, ref));
}

// Every glyph of a font, flattened at three pixel sizes with the error
// measured exactly (flatten/error.h), stays within the tolerance.
void check_flattening_error(const std::string& file, int index, std::size_t count) {
    const auto font = Font::load(file, index, {});
    ASSERT_TRUE(font);
    const double tolerance = 0.25;
    double worst = 0;
    std::size_t curves = 0;
    for (const double px : {9.0, 40.0, 160.0}) {
        const double s = px / font->metrics().units_per_em;
        const Affine to_device{s, 0, 0, -s, 0, 0};
        for (std::uint32_t g = 0; g < std::min(count, font->glyph_count()); ++g) {
            std::vector<Polyline> lines;
            const FlattenStats stats =
                flatten_path(font->outline(g), to_device, {tolerance}, lines, true);
            EXPECT_LE(stats.max_error, tolerance + 1e-9)
                << font->family() << " glyph " << g << " at " << px << " px";
            worst = std::max(worst, stats.max_error);
            curves += stats.curves_in;
        }
    }
    std::printf("  %s: %zu segments, max flattening error %.4f px\n", font->family().c_str(),
                curves, worst);
    // Glyphs do have curves that need several chords: the bound is not met
    // vacuously by lines alone.
    EXPECT_GT(worst, tolerance / 4);
}

TEST(GlyphFlattening, MeasuredErrorWithinTheToleranceTrueType) {
    check_flattening_error(kDejaVuSans, 0, 300);
}

TEST(GlyphFlattening, MeasuredErrorWithinTheToleranceCff) {
    if (!has_file(kNotoSansCjk)) GTEST_SKIP() << kNotoSansCjk << " (fonts-noto-cjk) missing";
    check_flattening_error(kNotoSansCjk, 0, 300);
}

// The glyph's outline as the font defines it, in font units: FreeType's own
// decomposition of the unscaled contours, at twice the scale and halved.
// TrueType places an on-curve point midway between two consecutive
// off-curve points; FT_Outline_Decompose computes it in integers, (a + b) / 2
// truncated, so at unit scale it is up to half a unit off, while with
// coordinates doubled (the `shift` of FT_Outline_Funcs) it is exact.
Path exact_outline(FT_Face face, std::uint32_t glyph) {
    Path contours;
    if (FT_Load_Glyph(face, glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) != 0) return contours;
    struct Emit {
        static Point pt(const FT_Vector* v) { return {v->x / 2.0, v->y / 2.0}; }
        static int move(const FT_Vector* to, void* p) {
            static_cast<Path*>(p)->move_to(pt(to));
            return 0;
        }
        static int line(const FT_Vector* to, void* p) {
            static_cast<Path*>(p)->line_to(pt(to));
            return 0;
        }
        static int conic(const FT_Vector* c, const FT_Vector* to, void* p) {
            static_cast<Path*>(p)->quad_to(pt(c), pt(to));
            return 0;
        }
        static int cubic(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* p) {
            static_cast<Path*>(p)->cubic_to(pt(c1), pt(c2), pt(to));
            return 0;
        }
    };
    const FT_Outline_Funcs funcs = {Emit::move, Emit::line, Emit::conic, Emit::cubic, 1, 0};
    FT_Outline_Decompose(&face->glyph->outline, &funcs, &contours);
    Path closed;
    for (Subpath sp : contours.subpaths()) {
        sp.closed = true;
        closed.add_subpath(sp);
    }
    return closed;
}

// Font::outline is the font's outline exactly: same contours, same
// segments, same control points, the implied on-curve points of TrueType
// included (nothing is approximated before the flattener).
TEST(GlyphOutline, TrueTypeImpliedOnCurvePointsAreExactMidpoints) {
    const auto font = Font::load(kDejaVuSans, 0, {});
    ASSERT_TRUE(font);
    FtFace ft(kDejaVuSans, 0);
    ASSERT_TRUE(ft.get());
    double worst = 0;
    std::uint32_t worst_glyph = 0;
    int off = 0;
    for (std::uint32_t g = 0; g < 400; ++g) {
        const double d = control_point_distance(font->outline(g), exact_outline(ft.get(), g));
        off += d > 0;
        if (d > worst) worst = d, worst_glyph = g;
    }
    EXPECT_EQ(worst, 0) << off << " of 400 glyphs are off their font's outline, by up to " << worst
                        << " font units (glyph " << worst_glyph << ")";
    // The reference does have the half units that integer midpoints lose.
    bool half_units = false;
    const Path o = exact_outline(ft.get(), font->glyph_index(U'o'));
    for (const Subpath& sp : o.subpaths())
        for (const Segment& s : sp.segments)
            for (const Point p : control_points(s))
                half_units |= p.x != std::floor(p.x) || p.y != std::floor(p.y);
    EXPECT_TRUE(half_units);
}

// What kinds of segment a glyph's outline holds.
struct SegmentKinds {
    std::size_t lines = 0, quads = 0, cubics = 0, conics = 0;
};

SegmentKinds kinds_of(const Path& p) {
    SegmentKinds k;
    for (const Subpath& sp : p.subpaths())
        for (const Segment& s : sp.segments) {
            if (std::holds_alternative<Line>(s)) ++k.lines;
            if (std::holds_alternative<QuadBez>(s)) ++k.quads;
            if (std::holds_alternative<CubicBez>(s)) ++k.cubics;
            if (std::holds_alternative<Conic>(s)) ++k.conics;
        }
    return k;
}

// Every contour is a closed loop (a glyph is an area), with as many
// subpaths as FreeType has contours and exactly FreeType's control box in
// font units: the outline is the font's own, nothing approximated or lost.
// TrueType stores quadratics, CFF cubics, and they stay so.
void check_outlines(const std::string& file, int index, bool cubic, std::size_t count) {
    const auto font = Font::load(file, index, {});
    ASSERT_TRUE(font);
    FtFace ft(file, index);
    ASSERT_TRUE(ft.get());
    SegmentKinds total;
    std::size_t empty = 0;
    for (std::uint32_t g = 0; g < std::min(count, font->glyph_count()); ++g) {
        const Path& p = font->outline(g);
        EXPECT_EQ(&p, &font->outline(g)) << "glyph " << g << " is read once and kept";
        ASSERT_EQ(FT_Load_Glyph(ft.get(), g, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING), 0);
        const FT_Outline& o = ft.get()->glyph->outline;
        EXPECT_EQ(p.subpaths().size(), std::size_t(o.n_contours)) << "glyph " << g;
        if (p.empty()) {
            ++empty;
            continue;
        }
        FT_BBox box;
        FT_Outline_Get_CBox(&o, &box);
        const Rect b = p.control_bounds();
        EXPECT_EQ(b.x0, double(box.xMin)) << "glyph " << g;
        EXPECT_EQ(b.y0, double(box.yMin)) << "glyph " << g;
        EXPECT_EQ(b.x1, double(box.xMax)) << "glyph " << g;
        EXPECT_EQ(b.y1, double(box.yMax)) << "glyph " << g;
        for (std::size_t i = 0; i < p.subpaths().size(); ++i) {
            const Subpath& sp = p.subpaths()[i];
            EXPECT_TRUE(sp.closed) << "glyph " << g << " contour " << i;
            ASSERT_FALSE(sp.segments.empty()) << "glyph " << g << " contour " << i;
            Point at = sp.start;
            for (const Segment& s : sp.segments) {
                EXPECT_EQ(segment_start(s), at) << "glyph " << g << " contour " << i;
                at = segment_end(s);
            }
            EXPECT_EQ(at, sp.start) << "glyph " << g << " contour " << i << " does not close";
        }
        const SegmentKinds k = kinds_of(p);
        total.lines += k.lines, total.quads += k.quads;
        total.cubics += k.cubics, total.conics += k.conics;
    }
    EXPECT_LT(empty, count / 10) << "most glyphs have outlines";
    EXPECT_GT(total.lines, 0u);
    EXPECT_EQ(total.conics, 0u);
    if (cubic) {
        EXPECT_GT(total.cubics, 0u);
        EXPECT_EQ(total.quads, 0u);
    } else {
        EXPECT_GT(total.quads, 0u);
        EXPECT_EQ(total.cubics, 0u);
    }
    // A round letter has curves of the font's kind.
    const SegmentKinds o = kinds_of(font->outline(font->glyph_index(U'o')));
    EXPECT_GT(cubic ? o.cubics : o.quads, 0u);
}

TEST(GlyphOutline, TrueTypeContoursAreClosedQuadratics) {
    check_outlines(kDejaVuSans, 0, false, 400);
}

TEST(GlyphOutline, CffContoursAreClosedCubics) {
    if (!has_file(kNotoSansCjk)) GTEST_SKIP() << kNotoSansCjk << " (fonts-noto-cjk) missing";
    check_outlines(kNotoSansCjk, 0, true, 400);
}

TEST(GlyphOutline, SpaceAndOutOfRangeGlyphsAreEmpty) {
    const auto font = Font::load(kDejaVuSans, 0, {});
    ASSERT_TRUE(font);
    const std::uint32_t space = font->glyph_index(U' ');
    ASSERT_NE(space, 0u);
    EXPECT_TRUE(font->outline(space).empty());
    EXPECT_GT(font->advance(space), 0);
    EXPECT_TRUE(font->outline(std::uint32_t(font->glyph_count())).empty());
    EXPECT_TRUE(font->outline(0xFFFFFFFFu).empty());
    EXPECT_EQ(font->advance(std::uint32_t(font->glyph_count()) + 5), 0);
    // The missing glyph itself (0) has an outline: the box drawn for a
    // character the font lacks.
    EXPECT_FALSE(font->outline(0).empty());
    EXPECT_EQ(font->glyph_index(U'\U0010FFFD'), 0u);
}

// Synthesized faces (FontSynthesis): a slant moves every control point by
// 0.2 of its height, exactly; emboldening grows each glyph by 1/24 em to
// the right and up, its left and bottom where they were (FreeType's
// FT_GlyphSlot_Embolden; glyphs whose extremes are stems, right angles and
// round sides: a sharp corner grows further, as a miter does); neither
// changes an advance.
TEST(GlyphOutline, SynthesizedBoldGrowsAndSlantShears) {
    const auto plain = Font::load(kDejaVuSans, 0, {});
    const auto bold = Font::load(kDejaVuSans, 0, {});
    const auto slanted = Font::load(kDejaVuSans, 0, {});
    ASSERT_TRUE(plain && bold && slanted);
    bold->set_synthesis({true, 0});
    slanted->set_synthesis({false, 0.2});
    const double strength = std::floor(plain->metrics().units_per_em / 24);
    for (const char32_t c : std::u32string(U"lHoOEn8")) {
        const std::uint32_t g = plain->glyph_index(c);
        Path sheared = plain->outline(g);
        sheared.transform(Affine{1, 0, 0.2, 1, 0, 0});
        EXPECT_EQ(control_point_distance(slanted->outline(g), sheared), 0) << char(c);
        const Rect p = plain->outline(g).control_bounds(), b = bold->outline(g).control_bounds();
        EXPECT_NEAR(b.x0, p.x0, 1) << char(c);
        EXPECT_NEAR(b.y0, p.y0, 1) << char(c);
        EXPECT_NEAR(b.x1, p.x1 + strength, 1) << char(c);
        EXPECT_NEAR(b.y1, p.y1 + strength, 1) << char(c);
        EXPECT_EQ(bold->advance(g), plain->advance(g));
        EXPECT_EQ(slanted->advance(g), plain->advance(g));
    }
}

// The x-height and cap height are the tops of x and H: what font-size-adjust
// scales by. Noto Sans has them in its OS/2 table (version 4).
TEST(FontLoad, MetricsFromTheOs2Table) {
    const auto font = Font::load("/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf", 0, {});
    ASSERT_TRUE(font);
    EXPECT_EQ(font->family(), "Noto Sans");
    const FontMetrics& m = font->metrics();
    EXPECT_EQ(m.units_per_em, 1000);
    EXPECT_GT(m.ascender, 0);
    EXPECT_LT(m.descender, 0);
    EXPECT_EQ(m.x_height, font->outline(font->glyph_index(U'x')).bounds().y1);
    EXPECT_EQ(m.cap_height, font->outline(font->glyph_index(U'H')).bounds().y1);
    EXPECT_GT(m.underline_thickness, 0);
    EXPECT_LT(m.underline_position, 0);
    EXPECT_GT(m.strikeout_position, 0);
}

// DejaVu Sans's OS/2 table is version 1, without sxHeight and sCapHeight;
// browsers then measure the glyphs x and H (Firefox's gfxFont, Skia's
// FreeType scaler) rather than guess half and 0.7 of the em: DejaVu's
// x-height is 0.547 em, which font-size-adjust would otherwise get 9% wrong.
TEST(FontLoad, XHeightAndCapHeightMeasuredWhenTheOs2TableLacksThem) {
    const auto font = Font::load(kDejaVuSans, 0, {});
    ASSERT_TRUE(font);
    EXPECT_EQ(font->family(), "DejaVu Sans");
    EXPECT_EQ(font->metrics().units_per_em, 2048);
    EXPECT_EQ(font->metrics().x_height, font->outline(font->glyph_index(U'x')).bounds().y1);
    EXPECT_EQ(font->metrics().cap_height, font->outline(font->glyph_index(U'H')).bounds().y1);
    EXPECT_GT(font->glyph_count(), 5000u);
}

// A file that is not a font, and one that does not exist, give null and say
// which file and why.
TEST(FontLoad, NotAFontIsRefusedWithAnError) {
    const std::filesystem::path garbage = std::filesystem::temp_directory_path() /
                                          ("casteljau_not_a_font_" + std::to_string(::getpid()));
    {
        std::ofstream out(garbage, std::ios::binary);
        for (int i = 0; i < 4096; ++i) out.put(char((i * 7919 + 13) % 251));
    }
    std::string error;
    EXPECT_EQ(Font::load(garbage.string(), 0, {}, &error), nullptr);
    EXPECT_NE(error.find(garbage.string()), std::string::npos) << error;
    std::filesystem::remove(garbage);

    error.clear();
    EXPECT_EQ(Font::load("/nonexistent/font.ttf", 0, {}, &error), nullptr);
    EXPECT_FALSE(error.empty());
    // A face index past the file's faces is not a font either.
    error.clear();
    EXPECT_EQ(Font::load(kDejaVuSans, 3, {}, &error), nullptr);
    EXPECT_FALSE(error.empty());
    // No error string asked for: still null, no crash.
    EXPECT_EQ(Font::load("/nonexistent/font.ttf", 0, {}), nullptr);
}

} // namespace
} // namespace casteljau
