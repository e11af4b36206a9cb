// <image> hrefs: data: URLs decode as browsers decode them (base64 with or
// without padding and whitespace, percent-escapes, the media type), and file
// references stay within the SVG's folder or the resources directory however
// they try to leave it (.., symlinks, absolute paths, prefix look-alikes,
// file: URLs), with no network access.
#include "casteljau/svg/resource_url.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

namespace casteljau {
namespace {

namespace fs = std::filesystem;

std::vector<unsigned char> bytes(std::string_view s) { return {s.begin(), s.end()}; }

DataUrl data_ok(std::string_view url) {
    std::string error = "stale";
    const auto d = parse_data_url(url, error);
    EXPECT_TRUE(d) << url;
    EXPECT_EQ(error, "") << url;
    return d.value_or(DataUrl{});
}

std::string data_error(std::string_view url) {
    std::string error;
    EXPECT_FALSE(parse_data_url(url, error)) << url;
    EXPECT_NE(error, "") << url;
    return error;
}

TEST(ResourceUrl, Base64WithAndWithoutPaddingAndWhitespace) {
    const DataUrl png = data_ok("data:image/png;base64,iVBORw0KGgo=");
    EXPECT_EQ(png.mime, "image/png");
    EXPECT_EQ(png.bytes, (std::vector<unsigned char>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}));
    EXPECT_EQ(data_ok("data:;base64,YWJj").bytes, bytes("abc"));
    EXPECT_EQ(data_ok("data:;base64,YWI=").bytes, bytes("ab"));
    EXPECT_EQ(data_ok("data:;base64,YWI").bytes, bytes("ab"));
    EXPECT_EQ(data_ok("data:;base64,YQ==").bytes, bytes("a"));
    EXPECT_EQ(data_ok("data:;base64,YQ").bytes, bytes("a"));
    EXPECT_EQ(data_ok("data:;base64,").bytes, bytes(""));
    EXPECT_EQ(data_ok("  data:image/gif;base64,\n  YW\tJ j\r\n Zg = = \n").bytes, bytes("abcf"));
    // Percent-escapes are decoded before base64: %2B is '+'.
    EXPECT_EQ(data_ok("data:;base64,%2B%2F%2B%2F").bytes,
              (std::vector<unsigned char>{0xfb, 0xff, 0xbf}));
}

TEST(ResourceUrl, Base64RoundTripsRandomBytesThroughWhitespace) {
    static const char* alphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::mt19937 rng(2397);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<unsigned char> in(rng() % 40);
        for (auto& b : in) b = static_cast<unsigned char>(rng());
        std::string enc;
        for (std::size_t i = 0; i < in.size(); i += 3) {
            const std::size_t n = std::min<std::size_t>(3, in.size() - i);
            std::uint32_t v = 0;
            for (std::size_t k = 0; k < 3; ++k) v = v << 8 | (k < n ? in[i + k] : 0);
            for (std::size_t k = 0; k < n + 1; ++k) enc += alphabet[v >> (18 - 6 * k) & 63];
            if (trial % 2) enc.append(3 - n, '=');
        }
        std::string url = "data:application/octet-stream;base64,";
        for (char c : enc) {
            url += c;
            if (rng() % 5 == 0) url += " \n\t"[rng() % 3];
        }
        EXPECT_EQ(data_ok(url).bytes, in) << url;
    }
}

TEST(ResourceUrl, PercentEncodedDataAndMediaType) {
    const DataUrl svg = data_ok("data:image/svg+xml;charset=utf-8,%3Csvg%3E%20%3C/svg%3E");
    EXPECT_EQ(svg.mime, "image/svg+xml");
    EXPECT_EQ(svg.bytes, bytes("<svg> </svg>"));
    // A '%' without two hex digits stays as it is, as browsers leave it.
    EXPECT_EQ(data_ok("data:,a%zz%4").bytes, bytes("a%zz%4"));
    EXPECT_EQ(data_ok("data:,hello").mime, "text/plain");
    const DataUrl upper = data_ok("DATA:Image/PNG ; BASE64,YWJj");
    EXPECT_EQ(upper.mime, "image/png");
    EXPECT_EQ(upper.bytes, bytes("abc"));
    // "base64" not after a ';' is data, not the encoding.
    EXPECT_EQ(data_ok("data:base64,YWJj").bytes, bytes("YWJj"));
}

TEST(ResourceUrl, MalformedDataUrlsAreErrors) {
    data_error("data:;base64,YW*j");
    data_error("data:;base64,Y");    // 4k + 1 characters
    data_error("data:;base64,YQ=x"); // '=' inside
    data_error("data:;base64,a==="); // three '='
    data_error("data:;base64,YWJjZA=== ");
    EXPECT_NE(data_error("data:image/png;base64").find("comma"), std::string::npos);
}

TEST(ResourceUrl, NotADataUrlIsNulloptWithoutError) {
    for (std::string_view url : {"image.png", "http://x/data:,a", "dat:,a", "", "data"}) {
        std::string error = "stale";
        EXPECT_FALSE(parse_data_url(url, error)) << url;
        EXPECT_EQ(error, "") << url;
    }
}

struct Tree {
    fs::path root;
    std::string svg, res;
    Tree() : root(fs::temp_directory_path() / ("casteljau_url_" + std::to_string(::getpid()))) {
        fs::remove_all(root);
        for (const char* d : {"svg/sub", "outside", "res", "svgx", "resx"})
            fs::create_directories(root / d);
        for (const char* f : {"svg/img.png", "svg/sub/deep.png", "svg/my pic.png",
                              "outside/secret.png", "res/r.png", "svgx/evil.png", "resx/a.png"})
            std::ofstream(root / f) << "x";
        fs::create_directory_symlink(root / "outside", root / "svg/link_out");
        fs::create_symlink(root / "svg/sub/deep.png", root / "svg/link_in");
        fs::create_symlink("../../outside/secret.png", root / "svg/sub/rel_out");
        svg = (root / "svg").string();
        res = (root / "res").string();
    }
    ~Tree() {
        std::error_code ec;
        fs::remove_all(root, ec);
    }
    std::string canonical(const char* f) const { return fs::canonical(root / f).string(); }
};

std::string resolved(std::string_view href, const std::string& dir, const std::string& res = "") {
    const ResourcePath r = resolve_resource_path(href, dir, res);
    EXPECT_EQ(r.error, "") << href;
    return r.path;
}

std::string refused(std::string_view href, const std::string& dir, const std::string& res = "") {
    const ResourcePath r = resolve_resource_path(href, dir, res);
    EXPECT_EQ(r.path, "") << href;
    EXPECT_NE(r.error, "") << href;
    return r.error;
}

bool outside(const std::string& error) {
    return error.find("outside the SVG's folder and the resources directory") != std::string::npos;
}

TEST(ResourceUrl, RelativePathsInsideTheSvgFolder) {
    const Tree t;
    EXPECT_EQ(resolved("img.png", t.svg), t.canonical("svg/img.png"));
    EXPECT_EQ(resolved("sub/deep.png", t.svg), t.canonical("svg/sub/deep.png"));
    EXPECT_EQ(resolved("./sub/../img.png", t.svg), t.canonical("svg/img.png"));
    EXPECT_EQ(resolved("img.png", t.svg + "/"), t.canonical("svg/img.png"));
    EXPECT_EQ(resolved("my%20pic.png", t.svg), t.canonical("svg/my pic.png"));
    EXPECT_EQ(resolved(" img.png?size=2#frag ", t.svg), t.canonical("svg/img.png"));
    // A symlink that stays inside is followed; the file need not exist yet.
    EXPECT_EQ(resolved("link_in", t.svg), t.canonical("svg/sub/deep.png"));
    EXPECT_EQ(resolved("nothere.png", t.svg),
              (fs::path(t.canonical("svg")) / "nothere.png").string());
}

TEST(ResourceUrl, EscapesAreRefused) {
    const Tree t;
    EXPECT_TRUE(outside(refused("../outside/secret.png", t.svg)));
    EXPECT_TRUE(outside(refused("sub/../../outside/secret.png", t.svg)));
    EXPECT_TRUE(outside(refused("sub/missing/../../../outside/secret.png", t.svg)));
    EXPECT_TRUE(outside(refused("%2E%2E/outside/secret.png", t.svg)));
    EXPECT_TRUE(outside(refused("link_out/secret.png", t.svg)));
    EXPECT_TRUE(outside(refused("sub/rel_out", t.svg)));
    EXPECT_TRUE(outside(refused((t.root / "outside/secret.png").string(), t.svg)));
    EXPECT_TRUE(outside(refused("/etc/passwd", t.svg)));
    // Prefix look-alikes: svgx is not within svg, resx not within res.
    EXPECT_TRUE(outside(refused("../svgx/evil.png", t.svg)));
    EXPECT_TRUE(outside(refused((t.root / "resx/a.png").string(), t.svg, t.res)));
    EXPECT_NE(refused("", t.svg), "");
    EXPECT_NE(refused("#frag", t.svg), "");
    EXPECT_NE(refused("a%00b.png", t.svg), "");
}

TEST(ResourceUrl, ResourcesDirectoryIsAllowed) {
    const Tree t;
    const std::string abs = (t.root / "res/r.png").string();
    EXPECT_TRUE(outside(refused(abs, t.svg)));
    EXPECT_EQ(resolved(abs, t.svg, t.res), t.canonical("res/r.png"));
    EXPECT_EQ(resolved("../res/r.png", t.svg, t.res), t.canonical("res/r.png"));
    EXPECT_EQ(resolved("file://" + abs, t.svg, t.res), t.canonical("res/r.png"));
    // The SVG's folder stays allowed alongside.
    EXPECT_EQ(resolved("img.png", t.svg, t.res), t.canonical("svg/img.png"));
}

TEST(ResourceUrl, FileUrls) {
    const Tree t;
    const std::string img = t.canonical("svg/img.png");
    EXPECT_EQ(resolved("file://" + img, t.svg), img);
    EXPECT_EQ(resolved("FILE://localhost" + img, t.svg), img);
    EXPECT_EQ(resolved("file:" + img, t.svg), img);
    EXPECT_EQ(resolved("file:img.png", t.svg), img);
    EXPECT_EQ(resolved("file:sub/deep.png#x", t.svg), t.canonical("svg/sub/deep.png"));
    EXPECT_TRUE(outside(refused("file://" + t.canonical("outside/secret.png"), t.svg)));
}

TEST(ResourceUrl, NetworkIsNeverUsed) {
    const Tree t;
    for (std::string_view href :
         {"http://example.com/a.png", "https://example.com/a.png", "HTTP://example.com/a.png",
          "ftp://example.com/a.png", "//example.com/a.png", "file://example.com/a.png",
          "file://localhost.example.com/a.png", "javascript:alert(1)", "blob:abc", "data:,a"}) {
        const std::string e = refused(href, t.svg, t.res);
        EXPECT_NE(e.find("network access is not allowed"), std::string::npos) << href << ": " << e;
    }
}

} // namespace
} // namespace casteljau
