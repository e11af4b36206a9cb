// <image>: image-rendering's nearest pixel (librsvg 2.54 ignores the
// property), SVG images drawn as vectors exactly as the same content inline,
// preserveAspectRatio and the image's own size, where an href may lead (the
// SVG's folder and the resources directory only, never the network), the
// limits (pixels, SVG images inside SVG images, elements), and opacity,
// transform and clip-path applied to an image.
#include "casteljau/render/renderer.h"
#include "casteljau/svg/reader.h"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include "pixels.h"

#include <gtest/gtest.h>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

namespace casteljau {
namespace {

namespace fs = std::filesystem;

// Strings built with +=, not "literal" + std::to_string(...): GCC 12 at -O3
// warns (-Wrestrict) about a false overlap in that operator+.

/// A folder of its own for each test (and each TempDir in it), removed after.
struct TempDir {
    fs::path path;
    TempDir() {
        static int count = 0;
        std::string name = "casteljau_image_";
        name += std::to_string(::getpid());
        name += '_';
        name += ::testing::UnitTest::GetInstance()->current_test_info()->name();
        name += '_';
        name += std::to_string(count++);
        path = fs::temp_directory_path() / name;
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::string operator/(const std::string& name) const { return (path / name).string(); }
    std::string str() const { return path.string(); }
};

/// Writes 8-bit RGBA pixels (straight alpha) as a PNG with OIIO's writer.
void write_png(const std::string& path, int w, int h, const std::vector<unsigned char>& rgba) {
    ASSERT_EQ(rgba.size(), std::size_t(w) * std::size_t(h) * 4);
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << path;
    const OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, rgba.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

void write_text(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::vector<unsigned char> file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

/// `a` then `b` (see above).
std::string cat(std::string a, const std::string& b) {
    a += b;
    return a;
}

std::string base64(const std::vector<unsigned char>& b) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < b.size(); i += 3) {
        const unsigned v = unsigned(b[i]) << 16 | (i + 1 < b.size() ? unsigned(b[i + 1]) << 8 : 0) |
                           (i + 2 < b.size() ? unsigned(b[i + 2]) : 0);
        out += digits[v >> 18 & 63];
        out += digits[v >> 12 & 63];
        out += i + 1 < b.size() ? digits[v >> 6 & 63] : '=';
        out += i + 2 < b.size() ? digits[v & 63] : '=';
    }
    return out;
}

/// Every byte but letters and digits as %XX.
std::string percent_encoded(const std::string& s) {
    static const char* hex = "0123456789ABCDEF";
    std::string out;
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        if (std::isalnum(c)) {
            out += ch;
        } else {
            out += '%';
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}

/// The CRC of PNG chunks (ISO/IEC 15948, annex D).
std::uint32_t crc32(const unsigned char* p, std::size_t n) {
    std::uint32_t c = 0xffffffffu;
    for (std::size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xffffffffu;
}

/// A PNG that declares w x h RGBA pixels in a valid IHDR, followed by an
/// IDAT whose body is cut short: its header is all a reader may look at.
std::vector<unsigned char> png_header_only(std::uint32_t w, std::uint32_t h) {
    std::vector<unsigned char> b{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13};
    const std::size_t type_at = b.size();
    for (const char c : {'I', 'H', 'D', 'R'}) b.push_back(static_cast<unsigned char>(c));
    for (const std::uint32_t v : {w, h})
        for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<unsigned char>(v >> s));
    for (const unsigned char c : {8, 6, 0, 0, 0}) b.push_back(c); // 8-bit RGBA
    const std::uint32_t crc = crc32(b.data() + type_at, b.size() - type_at);
    for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<unsigned char>(crc >> s));
    // An IDAT of 256 bytes, of which the zlib header alone is there.
    for (const int c : {0, 1, 0, 0, int('I'), int('D'), int('A'), int('T'), 0x78, 0x9c})
        b.push_back(static_cast<unsigned char>(c));
    return b;
}

constexpr const char* kSvgOpen = R"(<svg xmlns="http://www.w3.org/2000/svg" width=")";

/// An SVG document of w x h px around `body`.
std::string document(const std::string& body, int w, int h) {
    std::string s = kSvgOpen;
    s += std::to_string(w);
    s += "\" height=\"";
    s += std::to_string(h);
    s += "\">";
    s += body;
    s += "</svg>";
    return s;
}

struct Drawn {
    Canvas canvas;
    std::vector<SvgDiagnostic> warnings;
    std::string error;
};

Drawn draw(const SvgResult& doc, int w, int h) {
    Drawn d{Canvas(w, h), doc.warnings, doc.error};
    if (doc.scene) Renderer().render(*doc.scene, Affine::identity(), d.canvas, RenderOptions{});
    return d;
}

/// `body` in a w x h document read from the folder `dir` (its base_dir).
Drawn render(const std::string& body, int w, int h, const std::string& dir,
             SvgOptions options = {}) {
    options.base_dir = dir;
    const SvgResult doc = parse_svg(document(body, w, h), "t.svg", options);
    EXPECT_TRUE(doc.scene) << doc.error;
    return draw(doc, w, h);
}

std::string warnings_text(const std::vector<SvgDiagnostic>& ws) {
    std::string s;
    for (const SvgDiagnostic& w : ws) {
        s += w.text();
        s += '\n';
    }
    return s;
}

bool blank(const Canvas& c) {
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x)
            if (c.row(y)[x].a != 0.0f) return false;
    return true;
}

using testing::max_difference;

bool same(Premul p, Premul q) { return p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a; }

::testing::AssertionResult near(Premul p, Premul q, float tol) {
    if (std::fabs(p.r - q.r) <= tol && std::fabs(p.g - q.g) <= tol && std::fabs(p.b - q.b) <= tol &&
        std::fabs(p.a - q.a) <= tol)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "(" << p.r << ", " << p.g << ", " << p.b << ", " << p.a << ") is not (" << q.r << ", "
           << q.g << ", " << q.b << ", " << q.a << ")";
}

constexpr Premul kRed{1, 0, 0, 1}, kBlue{0, 0, 1, 1}, kGreen{0, 1, 0, 1}, kNone{0, 0, 0, 0};

/// red | blue, 2 x 1 px.
void write_red_blue(const std::string& path) {
    write_png(path, 2, 1, {255, 0, 0, 255, 0, 0, 255, 255});
}

void write_green(const std::string& path, int w, int h) {
    std::vector<unsigned char> px;
    for (int i = 0; i < w * h; ++i) px.insert(px.end(), {0, 255, 0, 255});
    write_png(path, w, h, px);
}

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

// --- where an href may lead ---------------------------------------------------

struct Folders {
    TempDir root;
    std::string svg, res;
    Folders() {
        fs::create_directories(root.path / "svg");
        fs::create_directories(root.path / "res");
        svg = root / "svg";
        res = root / "res";
        write_green(root / "outside.png", 2, 2);
        write_green(root / "svg/inside.png", 2, 2);
        write_green(root / "res/r.png", 2, 2);
        fs::create_symlink(root.path / "outside.png", root.path / "svg/link.png");
    }
};

/// The one warning of an image that is not drawn, naming the element.
void expect_refused(const Drawn& d, const std::string& href, const std::string& why) {
    ASSERT_EQ(d.warnings.size(), 1u) << href << ": " << warnings_text(d.warnings);
    EXPECT_EQ(d.warnings[0].element, "image") << href;
    EXPECT_EQ(d.warnings[0].line, 1) << href;
    EXPECT_NE(d.warnings[0].message.find(why), std::string::npos)
        << href << ": " << d.warnings[0].message;
    EXPECT_TRUE(blank(d.canvas)) << href;
}

std::string image_of(const std::string& href) {
    std::string s = R"(<image width="10" height="10" href=")";
    s += href;
    s += R"("/>)";
    return s;
}

TEST(ImageHref, OutsideTheSvgsFolderIsRefused) {
    const Folders f;
    expect_refused(render(image_of("../outside.png"), 10, 10, f.svg), "../outside.png", "outside");
    expect_refused(render(image_of(f.root / "outside.png"), 10, 10, f.svg), "absolute", "outside");
    expect_refused(render(image_of("link.png"), 10, 10, f.svg), "a symlink out", "outside");
    // Inside, it is drawn.
    const Drawn in = render(image_of("inside.png"), 10, 10, f.svg);
    EXPECT_TRUE(in.warnings.empty()) << warnings_text(in.warnings);
    EXPECT_TRUE(near(in.canvas.row(5)[5], kGreen, 1e-6f));
}

TEST(ImageHref, TheResourcesDirectoryIsAllowed) {
    const Folders f;
    expect_refused(render(image_of("../res/r.png"), 10, 10, f.svg), "../res/r.png", "outside");
    SvgOptions o;
    o.resources_dir = f.res;
    for (const std::string& href : {std::string("../res/r.png"), f.root / "res/r.png"}) {
        const Drawn d = render(image_of(href), 10, 10, f.svg, o);
        EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
        EXPECT_TRUE(near(d.canvas.row(5)[5], kGreen, 1e-6f)) << href;
    }
    // It allows nothing beyond itself.
    expect_refused(render(image_of("../outside.png"), 10, 10, f.svg, o), "../outside.png",
                   "outside");
}

TEST(ImageHref, TheNetworkIsNeverUsed) {
    const Folders f;
    for (const char* href :
         {"http://example.com/a.png", "https://example.com/a.png", "//example.com/a.png",
          "HTTP://192.0.2.1:81/a.svg", "ftp://example.com/a.png", "file://example.com/a.png"}) {
        const auto t0 = std::chrono::steady_clock::now();
        const Drawn d = render(image_of(href), 10, 10, f.svg);
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        expect_refused(d, href, "network access is not allowed");
        EXPECT_LT(s, 0.5) << href << ": no connection is attempted";
    }
}

TEST(ImageHref, AMissingFileIsAWarning) {
    const Folders f;
    expect_refused(render(image_of("nothere.png"), 10, 10, f.svg), "nothere.png",
                   "cannot be drawn");
    expect_refused(render(image_of("nothere.svg"), 10, 10, f.svg), "nothere.svg",
                   "cannot be drawn");
}

TEST(ImageHref, ReadSvgFileTakesTheFilesFolder) {
    // read_svg_file's base is the file's folder, not the current directory.
    const Folders f;
    write_text(f.root / "svg/doc.svg", document(image_of("inside.png"), 10, 10));
    write_text(f.root / "svg/out.svg", document(image_of("../outside.png"), 10, 10));
    const Drawn in = draw(read_svg_file(f.root / "svg/doc.svg"), 10, 10);
    EXPECT_TRUE(in.warnings.empty()) << in.error << warnings_text(in.warnings);
    EXPECT_TRUE(near(in.canvas.row(5)[5], kGreen, 1e-6f));
    expect_refused(draw(read_svg_file(f.root / "svg/out.svg"), 10, 10), "out.svg", "outside");
}

TEST(ImageHref, UnderStrictARefusedImageIsTheError) {
    const Folders f;
    SvgOptions o;
    o.strict = true;
    o.base_dir = f.svg;
    const SvgResult r =
        parse_svg(document(cat("\n", image_of("../outside.png")), 10, 10), "t.svg", o);
    EXPECT_FALSE(r.scene);
    EXPECT_EQ(r.error.rfind("t.svg:2: <image>: ", 0), 0u) << r.error;
    EXPECT_NE(r.error.find("outside the SVG's folder"), std::string::npos) << r.error;
}

TEST(ImageHref, TheMessageQuotesTheHrefOnce) {
    const Folders f;
    const Drawn d = render(image_of("../outside.png"), 10, 10, f.svg);
    ASSERT_EQ(d.warnings.size(), 1u);
    const std::string& m = d.warnings[0].message;
    EXPECT_EQ(m.find("'../outside.png'"), m.rfind("'../outside.png'")) << m;
}

TEST(ImageHref, AnSvgImagesHrefsAreResolvedAgainstItsOwnFolder) {
    // sub/pic.svg draws sub/px.png by "px.png"; a data: URL's SVG has no
    // folder of its own and takes the document's.
    const Folders f;
    fs::create_directories(f.root.path / "svg/sub");
    write_green(f.root / "svg/sub/px.png", 2, 2);
    write_text(f.root / "svg/sub/pic.svg", document(image_of("px.png"), 10, 10));
    const Drawn d = render(image_of("sub/pic.svg"), 10, 10, f.svg);
    EXPECT_TRUE(d.warnings.empty()) << warnings_text(d.warnings);
    EXPECT_TRUE(near(d.canvas.row(5)[5], kGreen, 1e-6f));
    const std::string inner = document(image_of("inside.png"), 10, 10);
    const Drawn data =
        render(image_of(cat("data:image/svg+xml;base64,", base64({inner.begin(), inner.end()}))),
               10, 10, f.svg);
    EXPECT_TRUE(data.warnings.empty()) << warnings_text(data.warnings);
    EXPECT_TRUE(near(data.canvas.row(5)[5], kGreen, 1e-6f));
    // An SVG image's own escape is refused, and told in the image's file.
    write_text(f.root / "svg/sub/esc.svg", document(image_of("../../outside.png"), 10, 10));
    const Drawn esc = render(image_of("sub/esc.svg"), 10, 10, f.svg);
    ASSERT_EQ(esc.warnings.size(), 1u) << warnings_text(esc.warnings);
    EXPECT_NE(esc.warnings[0].file.find("esc.svg"), std::string::npos) << esc.warnings[0].file;
    EXPECT_NE(esc.warnings[0].message.find("outside"), std::string::npos);
    EXPECT_TRUE(blank(esc.canvas));
}

// --- limits -------------------------------------------------------------------

TEST(ImageLimits, MoreThanMaxImagePixelsIsNotDrawn) {
    const TempDir dir;
    write_green(dir / "g.png", 4, 3);
    SvgOptions o;
    o.max_image_pixels = 11;
    expect_refused(render(image_of("g.png"), 10, 10, dir.str(), o), "12 > 11 px",
                   "exceeds the limit");
    o.max_image_pixels = 12;
    EXPECT_FALSE(blank(render(image_of("g.png"), 10, 10, dir.str(), o).canvas));
    // A header that declares 1e10 pixels is refused before anything is
    // decoded: at once, in a data: URL or a file.
    {
        const std::vector<unsigned char> b = png_header_only(100000, 100000);
        std::ofstream(dir / "huge.png", std::ios::binary)
            .write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
        const auto t0 = std::chrono::steady_clock::now();
        expect_refused(render(image_of("huge.png"), 10, 10, dir.str()), "huge.png",
                       "100000 x 100000 pixels exceeds the limit");
        expect_refused(
            render(image_of(cat("data:image/png;base64,", base64(b))), 10, 10, dir.str()),
            "data: huge.png", "100000 x 100000 pixels exceeds the limit");
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                  1.0);
    }
}

TEST(ImageLimits, AnSvgImageOfItselfStopsAtMaxImageNesting) {
    // a.svg draws a rectangle and itself at half size below it: 1 + 8
    // nested levels are drawn, then the 9th image is refused, once.
    const TempDir dir;
    std::string a = kSvgOpen;
    a += R"(64" height="64"><rect width="64" height="32" fill="#00ff00"/>)"
         "\n"
         R"(<image href="a.svg" x="16" y="32" width="32" height="32"/></svg>)";
    write_text(dir / "a.svg", a);
    const auto t0 = std::chrono::steady_clock::now();
    const SvgResult doc = read_svg_file(dir / "a.svg");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
    ASSERT_TRUE(doc.scene) << doc.error;
    ASSERT_EQ(doc.warnings.size(), 1u) << warnings_text(doc.warnings);
    EXPECT_EQ(doc.warnings[0].element, "image");
    EXPECT_EQ(doc.warnings[0].line, 2);
    EXPECT_NE(doc.warnings[0].message.find("nested deeper than"), std::string::npos)
        << doc.warnings[0].message;
    // Each level's rectangle: level k spans y from 64 (1 - 2^-k) over 32 / 2^k.
    const Drawn d = draw(doc, 64, 64);
    EXPECT_TRUE(near(d.canvas.row(10)[32], kGreen, 1e-6f));
    EXPECT_TRUE(near(d.canvas.row(40)[32], kGreen, 1e-6f)) << "level 1";
    EXPECT_TRUE(same(d.canvas.row(40)[10], kNone)) << "beside level 1";
    // A smaller limit draws fewer levels: with 1, only a.svg and one image of it.
    SvgOptions o;
    o.max_image_nesting = 1;
    const SvgResult one = read_svg_file(dir / "a.svg", o);
    ASSERT_TRUE(one.scene) << one.error;
    EXPECT_EQ(one.warnings.size(), 1u) << warnings_text(one.warnings);
    const Drawn d1 = draw(one, 64, 64);
    EXPECT_TRUE(near(d1.canvas.row(40)[32], kGreen, 1e-6f)) << "level 1";
    EXPECT_TRUE(same(d1.canvas.row(56)[32], kNone)) << "level 2 is not drawn";
    // None at all: the image is refused at once.
    o.max_image_nesting = 0;
    const SvgResult none = read_svg_file(dir / "a.svg", o);
    ASSERT_TRUE(none.scene) << none.error;
    EXPECT_EQ(none.warnings.size(), 1u) << warnings_text(none.warnings);
    EXPECT_TRUE(same(draw(none, 64, 64).canvas.row(40)[32], kNone));
}

TEST(ImageLimits, TheMessageNamesTheConfiguredNestingLimit) {
    // The warning of a.svg including itself says the limit the caller set
    // (8), not what is left of it at the level that gives up.
    const TempDir dir;
    std::string a = kSvgOpen;
    a += R"(8" height="8"><image href="a.svg" width="8" height="8"/></svg>)";
    write_text(dir / "a.svg", a);
    const SvgResult doc = read_svg_file(dir / "a.svg");
    ASSERT_TRUE(doc.scene) << doc.error;
    ASSERT_EQ(doc.warnings.size(), 1u) << warnings_text(doc.warnings);
    EXPECT_NE(doc.warnings[0].message.find("nested deeper than 8"), std::string::npos)
        << doc.warnings[0].message;
}

TEST(ImageLimits, AnSvgImagesElementsCountAgainstMaxElements) {
    const TempDir dir;
    std::string big = kSvgOpen;
    big += R"(10" height="10">)";
    for (int i = 0; i < 40; ++i) big += R"(<rect width="1" height="1"/>)";
    big += "</svg>";
    write_text(dir / "big.svg", big);
    SvgOptions o;
    o.max_elements = 60;
    o.base_dir = dir.str();
    // Once: 40 and a few; twice: over 60.
    const SvgResult once = parse_svg(document(R"(<image href="big.svg"/>)", 10, 10), "t.svg", o);
    EXPECT_TRUE(once.scene) << once.error;
    const SvgResult twice =
        parse_svg(document("<image href=\"big.svg\"/>\n<image href=\"big.svg\" x=\"5\"/>", 10, 10),
                  "t.svg", o);
    EXPECT_FALSE(twice.scene);
    EXPECT_NE(twice.error.find("t.svg:2: <image>: more than 60 elements, SVG images included"),
              std::string::npos)
        << twice.error;
    // The same through <use> of one image.
    const SvgResult used = parse_svg(
        document(R"(<image id="i" href="big.svg"/><use href="#i"/>)", 10, 10), "t.svg", o);
    EXPECT_FALSE(used.scene);
    EXPECT_NE(used.error.find("SVG images included"), std::string::npos) << used.error;
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
