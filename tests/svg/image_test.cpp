// <image>: image-rendering's nearest pixel (librsvg 2.54 ignores the
// property), SVG images drawn as vectors exactly as the same content inline,
// preserveAspectRatio and the image's own size, where an href may lead (the
// SVG's folder and the resources directory only, never the network), the
// limits (pixels, SVG images inside SVG images, elements), and opacity,
// transform and clip-path applied to an image.
#include "image_files.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

using namespace testing;

// --- image-rendering --------------------------------------------------------

TEST(ImageRendering, NearestPixelUnderPixelatedOptimizeSpeedAndCrispEdges) {
    const TempDir dir;
    write_red_blue(dir / "rb.png");
    for (const char* attr :
         {R"(image-rendering="pixelated")", R"(style="image-rendering:optimizeSpeed")",
          R"(image-rendering="crisp-edges")", R"(style="image-rendering:pixelated")"}) {
        std::string body = R"(<image href="rb.png" width="20" height="10" )";
        body += attr;
        body += "/>";
        const Drawn d = render(body, 20, 10, dir.str());
        EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
        for (int y = 0; y < 10; ++y)
            for (int x = 0; x < 20; ++x)
                EXPECT_TRUE(same(d.canvas.row(y)[x], x < 10 ? kRed : kBlue))
                    << attr << " (" << x << ", " << y << ")";
    }
}

TEST(ImageRendering, SmoothByDefaultBlendsTheMiddleColumns) {
    const TempDir dir;
    write_red_blue(dir / "rb.png");
    for (const char* attr :
         {"", R"(image-rendering="auto")", R"(image-rendering="optimizeQuality")",
          R"(image-rendering="smooth")"}) {
        std::string body = R"(<image href="rb.png" width="20" height="10" )";
        body += attr;
        body += "/>";
        const Drawn d = render(body, 20, 10, dir.str());
        for (const int x : {9, 10}) {
            const Premul p = d.canvas.row(5)[x];
            EXPECT_GT(p.r, 0.2f) << attr << " column " << x;
            EXPECT_GT(p.b, 0.2f) << attr << " column " << x;
            EXPECT_NEAR(p.r + p.b, 1.0f, 1e-5f) << attr << " column " << x;
            EXPECT_NEAR(p.a, 1.0f, 1e-6f) << attr << " column " << x;
        }
        EXPECT_GT(d.canvas.row(5)[9].r, d.canvas.row(5)[10].r)
            << attr << ": red fades to the right";
        // The edge pixels extend: the outer columns are the pixels' own colors.
        EXPECT_TRUE(near(d.canvas.row(5)[0], kRed, 1e-6f)) << attr;
        EXPECT_TRUE(near(d.canvas.row(5)[19], kBlue, 1e-6f)) << attr;
    }
}

// --- SVG images ---------------------------------------------------------------

// Shapes, a stroke, a gradient, a pattern, a clip path and a mask: all
// resolved by the image's own reader, then moved into the viewport.
constexpr const char* kInnerContent =
    R"svg(<linearGradient id="lg" x2="0" y2="1"><stop offset="0" stop-color="#ffe08a"/>)svg"
    R"svg(<stop offset="1" stop-color="#8ae0ff"/></linearGradient>)svg"
    R"svg(<pattern id="pt" patternUnits="userSpaceOnUse" width="3.3" height="2.7">)svg"
    R"svg(<circle cx="1" cy="1" r="0.8" fill="#208020"/></pattern>)svg"
    R"svg(<clipPath id="cp"><circle cx="30" cy="10" r="8.5"/></clipPath>)svg"
    R"svg(<mask id="mk"><rect x="2" y="2" width="10" height="16" fill="#808080"/></mask>)svg"
    R"svg(<rect x="1.3" y="0.6" width="37.1" height="18.7" fill="url(#lg)"/>)svg"
    R"svg(<circle cx="12.3" cy="9.7" r="7.9" fill="#3366cc" fill-opacity="0.8"/>)svg"
    R"svg(<path d="M22 3 C 30 0 37 12 33 17.2 L 24.5 16 Z" fill="#cc6633" stroke="#000")svg"
    R"svg( stroke-width="0.7"/>)svg"
    R"svg(<rect x="20" y="1" width="19" height="18" fill="url(#pt)" clip-path="url(#cp)"/>)svg"
    R"svg(<rect x="1" y="1" width="14" height="18" fill="#a02040" mask="url(#mk)"/>)svg";

std::string inner_svg() {
    std::string s = kSvgOpen;
    s += R"(40" height="20" viewBox="0 0 40 20">)";
    s += kInnerContent;
    s += "</svg>";
    return s;
}

TEST(SvgImage, DrawsAsTheSameContentInlineInEveryForm) {
    // The image's view box is the SVG's size, 40 x 20, fitted into the
    // viewport as a nested <svg> with that viewBox is: vectors at the
    // device resolution, not a resampled picture.
    const TempDir dir;
    const std::string inner = inner_svg();
    write_text(dir / "inner.svg", inner);
    std::vector<std::string> hrefs{
        "inner.svg", cat("data:image/svg+xml;base64,", base64({inner.begin(), inner.end()}))};
    std::string encoded = "data:image/svg+xml;charset=utf-8,";
    encoded += percent_encoded(inner);
    hrefs.push_back(encoded);
    const char* placements[] = {
        R"(x="7" y="11" width="60" height="50")",
        R"(x="7" y="11" width="60" height="50" preserveAspectRatio="xMinYMax meet")",
        R"(x="3" y="4" width="30" height="70" preserveAspectRatio="xMidYMid slice")",
        R"(x="3" y="4" width="70" height="20" preserveAspectRatio="xMaxYMin slice")",
        R"(x="2" y="9" width="75" height="13" preserveAspectRatio="none")"};
    for (const char* at : placements) {
        std::string inline_body = "<svg ";
        inline_body += at;
        inline_body += R"( viewBox="0 0 40 20">)";
        inline_body += kInnerContent;
        inline_body += "</svg>";
        const Drawn want = render(inline_body, 80, 80, dir.str());
        EXPECT_FALSE(blank(want.canvas));
        for (const std::string& href : hrefs) {
            std::string body = "<image ";
            body += at;
            body += " href=\"";
            body += href;
            body += "\"/>";
            const Drawn got = render(body, 80, 80, dir.str());
            EXPECT_TRUE(got.warnings.empty()) << warnings_text(got.warnings);
            EXPECT_LE(max_difference(got.canvas, want.canvas), 1e-5f)
                << at << " " << href.substr(0, 40);
        }
    }
}

TEST(SvgImage, IsDrawnAsVectorsWhenScaledUp) {
    // A 4 x 4 SVG drawn 80 x 80: the circle's edge is as sharp as a circle
    // drawn there (exact-area coverage), not a 4-pixel picture blown up.
    const TempDir dir;
    std::string tiny = kSvgOpen;
    tiny += R"(4" height="4"><circle cx="2" cy="2" r="1.5" fill="#000"/></svg>)";
    write_text(dir / "tiny.svg", tiny);
    const Drawn got =
        render(R"(<image href="tiny.svg" width="80" height="80"/>)", 80, 80, dir.str());
    const Drawn want = render(R"(<circle cx="40" cy="40" r="30" fill="#000"/>)", 80, 80, dir.str());
    EXPECT_LE(max_difference(got.canvas, want.canvas), 1e-5f);
    EXPECT_EQ(got.canvas.row(40)[9].a, 0.0f);
    EXPECT_EQ(got.canvas.row(40)[11].a, 1.0f);
}

// --- preserveAspectRatio and size ---------------------------------------------

TEST(ImageFit, MeetLeavesTheLetterboxTransparent) {
    const TempDir dir;
    write_red_blue(dir / "rb.png");
    // 2 x 1 into 40 x 40: 40 x 20, centred: rows 10..29.
    const Drawn mid =
        render(R"(<image href="rb.png" width="40" height="40" image-rendering="pixelated"/>)", 60,
               60, dir.str());
    for (const int x : {1, 19, 20, 38}) {
        EXPECT_TRUE(same(mid.canvas.row(9)[x], kNone)) << x;
        EXPECT_TRUE(same(mid.canvas.row(10)[x], x < 20 ? kRed : kBlue)) << x;
        EXPECT_TRUE(same(mid.canvas.row(29)[x], x < 20 ? kRed : kBlue)) << x;
        EXPECT_TRUE(same(mid.canvas.row(30)[x], kNone)) << x;
    }
    const Drawn top =
        render(R"(<image href="rb.png" width="40" height="40" image-rendering="pixelated"
        preserveAspectRatio="xMinYMin meet"/>)",
               60, 60, dir.str());
    EXPECT_TRUE(same(top.canvas.row(0)[5], kRed));
    EXPECT_TRUE(same(top.canvas.row(19)[25], kBlue));
    EXPECT_TRUE(same(top.canvas.row(20)[5], kNone));
    const Drawn bottom = render(R"(<image href="rb.png" y="5" width="40" height="40"
        image-rendering="pixelated" preserveAspectRatio="xMaxYMax"/>)",
                                60, 60, dir.str());
    EXPECT_TRUE(same(bottom.canvas.row(24)[5], kNone));
    EXPECT_TRUE(same(bottom.canvas.row(25)[5], kRed));
    EXPECT_TRUE(same(bottom.canvas.row(44)[39], kBlue));
    EXPECT_TRUE(same(bottom.canvas.row(45)[5], kNone));
}

TEST(ImageFit, SliceIsClippedToTheViewport) {
    const TempDir dir;
    write_red_blue(dir / "rb.png");
    // 2 x 1 sliced into 40 x 40 at (10, 10): 80 x 40, centred: x -10..70,
    // red up to 30, blue from 30; only 10..50 shows.
    const Drawn d = render(R"(<image href="rb.png" x="10" y="10" width="40" height="40"
        image-rendering="pixelated" preserveAspectRatio="xMidYMid slice"/>)",
                           70, 70, dir.str());
    EXPECT_TRUE(same(d.canvas.row(30)[9], kNone)) << "left of the viewport";
    EXPECT_TRUE(same(d.canvas.row(30)[10], kRed));
    EXPECT_TRUE(same(d.canvas.row(30)[29], kRed));
    EXPECT_TRUE(same(d.canvas.row(30)[30], kBlue));
    EXPECT_TRUE(same(d.canvas.row(30)[49], kBlue));
    EXPECT_TRUE(same(d.canvas.row(30)[50], kNone)) << "right of the viewport";
    EXPECT_TRUE(same(d.canvas.row(9)[30], kNone));
    EXPECT_TRUE(same(d.canvas.row(49)[30], kBlue));
    EXPECT_TRUE(same(d.canvas.row(50)[30], kNone));
}

TEST(ImageFit, NoneStretches) {
    const TempDir dir;
    write_red_blue(dir / "rb.png");
    const Drawn d = render(R"(<image href="rb.png" width="30" height="40"
        image-rendering="pixelated" preserveAspectRatio="none"/>)",
                           50, 50, dir.str());
    for (const int y : {0, 20, 39}) {
        EXPECT_TRUE(same(d.canvas.row(y)[0], kRed)) << y;
        EXPECT_TRUE(same(d.canvas.row(y)[14], kRed)) << y;
        EXPECT_TRUE(same(d.canvas.row(y)[15], kBlue)) << y;
        EXPECT_TRUE(same(d.canvas.row(y)[29], kBlue)) << y;
        EXPECT_TRUE(same(d.canvas.row(y)[30], kNone)) << y;
    }
    EXPECT_TRUE(same(d.canvas.row(40)[5], kNone));
}

TEST(ImageFit, AbsentOrAutoSizeIsTheImagesAndOneSideKeepsTheAspectRatio) {
    const TempDir dir;
    write_red_blue(dir / "rb.png");
    for (const char* size : {"", R"(width="auto" height="auto")", R"(width="auto")"}) {
        std::string body = R"(<image href="rb.png" x="3" y="2" image-rendering="pixelated" )";
        body += size;
        body += "/>";
        const Drawn d = render(body, 10, 10, dir.str());
        EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
        EXPECT_TRUE(same(d.canvas.row(2)[3], kRed)) << size;
        EXPECT_TRUE(same(d.canvas.row(2)[4], kBlue)) << size;
        EXPECT_TRUE(same(d.canvas.row(2)[5], kNone)) << size;
        EXPECT_TRUE(same(d.canvas.row(3)[3], kNone)) << size;
    }
    // width 40 alone: height 20; height 10 alone: width 20.
    const Drawn w = render(R"(<image href="rb.png" width="40" image-rendering="pixelated"/>)", 50,
                           50, dir.str());
    EXPECT_TRUE(same(w.canvas.row(19)[19], kRed));
    EXPECT_TRUE(same(w.canvas.row(19)[20], kBlue));
    EXPECT_TRUE(same(w.canvas.row(19)[39], kBlue));
    EXPECT_TRUE(same(w.canvas.row(20)[20], kNone));
    EXPECT_TRUE(same(w.canvas.row(10)[40], kNone));
    const Drawn h =
        render(R"(<image href="rb.png" height="10" width="auto" image-rendering="pixelated"/>)", 50,
               50, dir.str());
    EXPECT_TRUE(same(h.canvas.row(9)[9], kRed));
    EXPECT_TRUE(same(h.canvas.row(9)[19], kBlue));
    EXPECT_TRUE(same(h.canvas.row(9)[20], kNone));
    EXPECT_TRUE(same(h.canvas.row(10)[5], kNone));
    // An SVG image's size is its width and height.
    std::string svg = kSvgOpen;
    svg += R"(6" height="3"><rect width="6" height="3" fill="#00ff00"/></svg>)";
    write_text(dir / "g.svg", svg);
    const Drawn s =
        render(R"(<image href="g.svg" x="1" y="1"/><image href="g.svg" x="1" y="10" width="12"/>)",
               20, 20, dir.str());
    EXPECT_TRUE(near(s.canvas.row(3)[6], kGreen, 1e-6f));
    EXPECT_TRUE(same(s.canvas.row(4)[6], kNone));
    EXPECT_TRUE(same(s.canvas.row(3)[7], kNone));
    EXPECT_TRUE(near(s.canvas.row(15)[12], kGreen, 1e-6f));
    EXPECT_TRUE(same(s.canvas.row(16)[12], kNone));
    EXPECT_TRUE(same(s.canvas.row(15)[13], kNone));
}

TEST(ImageFit, ARasterDataUrlDrawsAsItsFile) {
    const TempDir dir;
    write_png(dir / "px.png", 3, 2, {255, 0,  0,  255, 0,   255, 0,  128, 0,   0,   255, 255,
                                     10,  20, 30, 255, 200, 100, 50, 0,   255, 255, 255, 64});
    std::string body =
        R"(<image x="2.5" y="1.25" width="31" height="17" href="data:image/png;base64,)";
    body += base64(file_bytes(dir / "px.png"));
    body += R"("/>)";
    const Drawn data = render(body, 40, 20, dir.str());
    const Drawn file = render(R"(<image x="2.5" y="1.25" width="31" height="17" href="px.png"/>)",
                              40, 20, dir.str());
    EXPECT_TRUE(data.warnings.empty()) << warnings_text(data.warnings);
    EXPECT_FALSE(blank(file.canvas));
    EXPECT_EQ(max_difference(data.canvas, file.canvas), 0.0f);
}

// --- effects on an image ------------------------------------------------------

TEST(ImageEffects, OpacityTransformAndClipPathApply) {
    const TempDir dir;
    write_green(dir / "g.png", 2, 2);
    const Drawn op =
        render(R"(<image href="g.png" width="40" height="40" opacity="0.5"/>)", 50, 50, dir.str());
    EXPECT_TRUE(near(op.canvas.row(20)[20], {0, 0.5f, 0, 0.5f}, 1e-6f));
    const Drawn tr = render(
        R"svg(<image href="g.png" width="20" height="20" transform="translate(25 5) scale(1 2)"/>)svg",
        50, 50, dir.str());
    EXPECT_TRUE(same(tr.canvas.row(10)[10], kNone));
    EXPECT_TRUE(near(tr.canvas.row(10)[30], kGreen, 1e-6f));
    EXPECT_TRUE(near(tr.canvas.row(44)[44], kGreen, 1e-6f)) << "scaled down to y 45";
    EXPECT_TRUE(same(tr.canvas.row(46)[30], kNone));
    const Drawn cl = render(R"svg(<clipPath id="c"><circle cx="20" cy="20" r="15"/></clipPath>
        <image href="g.png" width="40" height="40" clip-path="url(#c)"/>)svg",
                            50, 50, dir.str());
    EXPECT_TRUE(near(cl.canvas.row(20)[20], kGreen, 1e-6f));
    EXPECT_TRUE(same(cl.canvas.row(2)[2], kNone)) << "outside the circle";
    EXPECT_TRUE(same(cl.canvas.row(20)[37], kNone)) << "outside the circle";
    // The clip's edge is the circle's exact coverage.
    const Drawn disc =
        render(R"(<circle cx="20" cy="20" r="15" fill="#00ff00"/>)", 50, 50, dir.str());
    EXPECT_LE(max_difference(cl.canvas, disc.canvas), 1e-5f);
    // And a mask: half luminance.
    const Drawn mk = render(
        R"svg(<mask id="m"><rect width="50" height="50" fill="#fff" fill-opacity="0.5"/></mask>
        <image href="g.png" width="40" height="40" mask="url(#m)"/>)svg",
        50, 50, dir.str());
    EXPECT_TRUE(near(mk.canvas.row(20)[20], {0, 0.5f, 0, 0.5f}, 1e-5f));
}

TEST(ImageEffects, InAPatternAndInAMask) {
    // An image as a pattern's content tiles; as a mask's, its luminance masks.
    const TempDir dir;
    write_red_blue(dir / "rb.png");
    write_png(dir / "gray.png", 1, 1, {128, 128, 128, 255});
    const Drawn p =
        render(R"svg(<pattern id="p" patternUnits="userSpaceOnUse" width="10" height="5">
        <image href="rb.png" width="10" height="5" image-rendering="pixelated"/></pattern>
        <rect width="40" height="20" fill="url(#p)"/>)svg",
               40, 20, dir.str());
    for (const int x : {2, 12, 32})
        for (const int y : {1, 6, 17}) {
            EXPECT_TRUE(near(p.canvas.row(y)[x], kRed, 1e-6f)) << x << ", " << y;
            EXPECT_TRUE(near(p.canvas.row(y)[x + 5], kBlue, 1e-6f)) << x + 5 << ", " << y;
        }
    const Drawn m =
        render(R"svg(<mask id="m" maskUnits="userSpaceOnUse" x="0" y="0" width="40" height="20">
        <image href="gray.png" width="20" height="20"/></mask>
        <rect width="40" height="20" fill="#fff" mask="url(#m)"/>)svg",
               40, 20, dir.str());
    // 128/255 gray: its luminance is 128/255 (the weights sum to 1).
    EXPECT_NEAR(m.canvas.row(10)[10].a, 128.0f / 255, 1e-5f);
    EXPECT_EQ(m.canvas.row(10)[30].a, 0.0f) << "no image there: luminance 0";
}

TEST(ImageEffects, OnAnSvgImageToo) {
    const TempDir dir;
    std::string svg = kSvgOpen;
    svg += R"(4" height="4"><rect width="4" height="4" fill="#00ff00"/></svg>)";
    write_text(dir / "g.svg", svg);
    const Drawn d =
        render(R"svg(<clipPath id="c"><rect x="0" y="0" width="20" height="50"/></clipPath>
        <image href="g.svg" width="40" height="40" opacity="0.5" transform="translate(5 5)" clip-path="url(#c)"/>)svg",
               50, 50, dir.str());
    EXPECT_TRUE(near(d.canvas.row(20)[10], {0, 0.5f, 0, 0.5f}, 1e-6f));
    EXPECT_TRUE(same(d.canvas.row(20)[30], kNone)) << "clipped (in the image's user space)";
    EXPECT_TRUE(same(d.canvas.row(2)[10], kNone)) << "moved down by 5";
}

} // namespace
} // namespace casteljau
