// Image files and SVG documents for the <image> tests (tests/svg/image_test.cpp,
// tests/svg/image_href_test.cpp): folders of their own, PNGs written with
// OpenImageIO or by hand, data: URL encodings, and rendering a document.
#pragma once

#include "casteljau/render/renderer.h"
#include "casteljau/svg/reader.h"
#include "pixels.h"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

namespace casteljau::testing {

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
inline void write_png(const std::string& path, int w, int h,
                      const std::vector<unsigned char>& rgba) {
    ASSERT_EQ(rgba.size(), std::size_t(w) * std::size_t(h) * 4);
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << path;
    const OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, rgba.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

inline void write_text(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline std::vector<unsigned char> file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

/// `a` then `b` (see above).
inline std::string cat(std::string a, const std::string& b) {
    a += b;
    return a;
}

inline std::string base64(const std::vector<unsigned char>& b) {
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
inline std::string percent_encoded(const std::string& s) {
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
inline std::uint32_t crc32(const unsigned char* p, std::size_t n) {
    std::uint32_t c = 0xffffffffu;
    for (std::size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xffffffffu;
}

/// A PNG that declares w x h RGBA pixels in a valid IHDR, followed by an
/// IDAT whose body is cut short: its header is all a reader may look at.
inline std::vector<unsigned char> png_header_only(std::uint32_t w, std::uint32_t h) {
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

inline constexpr const char* kSvgOpen = R"(<svg xmlns="http://www.w3.org/2000/svg" width=")";

/// An SVG document of w x h px around `body`.
inline std::string document(const std::string& body, int w, int h) {
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

inline Drawn draw(const SvgResult& doc, int w, int h) {
    Drawn d{Canvas(w, h), doc.warnings, doc.error};
    if (doc.scene) Renderer().render(*doc.scene, Affine::identity(), d.canvas, RenderOptions{});
    return d;
}

/// `body` in a w x h document read from the folder `dir` (its base_dir).
inline Drawn render(const std::string& body, int w, int h, const std::string& dir,
                    SvgOptions options = {}) {
    options.base_dir = dir;
    const SvgResult doc = parse_svg(document(body, w, h), "t.svg", options);
    EXPECT_TRUE(doc.scene) << doc.error;
    return draw(doc, w, h);
}

inline std::string warnings_text(const std::vector<SvgDiagnostic>& ws) {
    std::string s;
    for (const SvgDiagnostic& w : ws) {
        s += w.text();
        s += '\n';
    }
    return s;
}

inline bool blank(const Canvas& c) {
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x)
            if (c.row(y)[x].a != 0.0f) return false;
    return true;
}

inline bool same(Premul p, Premul q) {
    return p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a;
}

inline ::testing::AssertionResult near(Premul p, Premul q, float tol) {
    if (std::fabs(p.r - q.r) <= tol && std::fabs(p.g - q.g) <= tol && std::fabs(p.b - q.b) <= tol &&
        std::fabs(p.a - q.a) <= tol)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "(" << p.r << ", " << p.g << ", " << p.b << ", " << p.a << ") is not (" << q.r << ", "
           << q.g << ", " << q.b << ", " << q.a << ")";
}

inline constexpr Premul kRed{1, 0, 0, 1}, kBlue{0, 0, 1, 1}, kGreen{0, 1, 0, 1}, kNone{0, 0, 0, 0};

/// red | blue, 2 x 1 px.
inline void write_red_blue(const std::string& path) {
    write_png(path, 2, 1, {255, 0, 0, 255, 0, 0, 255, 255});
}

inline void write_green(const std::string& path, int w, int h) {
    // Sized at once: GCC 12 at -O3 takes insert() of an initializer list in
    // a loop for an overflow (-Wstringop-overflow) once this is inlined.
    std::vector<unsigned char> px(std::size_t(w) * std::size_t(h) * 4, 0);
    for (std::size_t i = 0; i < px.size(); i += 4) px[i + 1] = px[i + 3] = 255;
    write_png(path, w, h, px);
}

} // namespace casteljau::testing
