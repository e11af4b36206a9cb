// <image> hrefs and limits: where an href may lead (the SVG's folder and the
// resources directory only, never the network), and the limits on pixels,
// on SVG images inside SVG images and on the elements they add.
#include "cpu_time.h"
#include "image_files.h"

#include <atomic>
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

// Every socket this process opens, and every name it looks up, counted: a
// definition in the executable comes before libc's in the dynamic linker's
// lookup, so the calls of the libraries the reader uses (OpenImageIO, and
// whatever they load) land here too, and go on to the next definition. (A
// lookup opens its sockets inside libc, past socket(): hence getaddrinfo.)
namespace {
std::atomic<int> g_network_calls{0};

template <class F>
F next_definition(const char* name) {
    return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}
} // namespace

extern "C" int socket(int domain, int type, int protocol) noexcept {
    ++g_network_calls;
    static const auto next = next_definition<int (*)(int, int, int)>("socket");
    return next(domain, type, protocol);
}

extern "C" int getaddrinfo(const char* node, const char* service, const addrinfo* hints,
                           addrinfo** res) {
    ++g_network_calls;
    static const auto next =
        next_definition<int (*)(const char*, const char*, const addrinfo*, addrinfo**)>(
            "getaddrinfo");
    return next(node, service, hints, res);
}

namespace casteljau {
namespace {

using namespace testing;

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
    // The count sees the calls of any library: the names as the dynamic
    // linker gives them to one (not this file's own calls, which bind here
    // at link time). A numeric host is looked up without the network.
    const int before = g_network_calls;
    const auto any_socket = reinterpret_cast<int (*)(int, int, int)>(dlsym(RTLD_DEFAULT, "socket"));
    const auto any_lookup =
        reinterpret_cast<int (*)(const char*, const char*, const addrinfo*, addrinfo**)>(
            dlsym(RTLD_DEFAULT, "getaddrinfo"));
    close(any_socket(AF_UNIX, SOCK_STREAM, 0));
    addrinfo hints{};
    hints.ai_flags = AI_NUMERICHOST;
    addrinfo* found = nullptr;
    if (any_lookup("127.0.0.1", nullptr, &hints, &found) == 0) freeaddrinfo(found);
    ASSERT_EQ(g_network_calls, before + 2) << "the count is not live";
    for (const char* href :
         {"http://example.com/a.png", "https://example.com/a.png", "//example.com/a.png",
          "HTTP://192.0.2.1:81/a.svg", "ftp://example.com/a.png", "file://example.com/a.png"}) {
        const int calls = g_network_calls;
        for (const std::string& element :
             {image_of(href), cat(cat(R"(<use href=")", href), "\"/>")}) {
            const Drawn d = render(element, 10, 10, f.svg);
            ASSERT_EQ(d.warnings.size(), 1u) << href << ": " << warnings_text(d.warnings);
            EXPECT_NE(d.warnings[0].message.find("network access is not allowed"),
                      std::string::npos)
                << d.warnings[0].message;
        }
        const std::string sheet = cat(cat("<style>@import '", href), "';</style>");
        EXPECT_EQ(render(sheet, 10, 10, f.svg).warnings.size(), 1u) << href;
        EXPECT_EQ(g_network_calls, calls) << href << ": no name is looked up, no connection made";
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
        const double t0 = cpu_seconds();
        expect_refused(render(image_of("huge.png"), 10, 10, dir.str()), "huge.png",
                       "100000 x 100000 pixels exceeds the limit");
        expect_refused(
            render(image_of(cat("data:image/png;base64,", base64(b))), 10, 10, dir.str()),
            "data: huge.png", "100000 x 100000 pixels exceeds the limit");
        EXPECT_LT(cpu_seconds() - t0, 1.0) << "CPU seconds";
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
    const double t0 = cpu_seconds();
    const SvgResult doc = read_svg_file(dir / "a.svg");
    EXPECT_LT(cpu_seconds() - t0, 5.0) << "CPU seconds";
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

} // namespace
} // namespace casteljau
