#include "casteljau/io/canvas_write.h"
#include "casteljau/io/image_write.h"
#include "casteljau/paint/straight_rgba.h"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <utility>
#include <vector>

namespace casteljau {
namespace {

namespace fs = std::filesystem;

struct TempDir {
    fs::path path;
    TempDir() : path(fs::temp_directory_path() / ("casteljau_io_" + std::to_string(::getpid()))) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::permissions(path, fs::perms::owner_all, ec);
        fs::remove_all(path, ec);
    }
};

std::vector<float> gradient(int w, int h) {
    std::vector<float> px(std::size_t(w * h * 4));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = &px[std::size_t((y * w + x) * 4)];
            p[0] = float(x) / float(w - 1), p[1] = float(y) / float(h - 1), p[2] = 0.5f, p[3] = 1;
        }
    return px;
}

// The format follows the extension in any case: ".TIF" is TIFF (float) as
// ".tif" is, where the float test once listed only some spellings.
TEST(ImageWrite, ExtensionsPickTheFormatInAnyCase) {
    EXPECT_EQ(image_extension("out/A.PnG"), ".png");
    for (const char* f : {"a.exr", "a.EXR", "a.tif", "a.Tif", "a.TIFF"})
        EXPECT_TRUE(stores_float(f)) << f;
    for (const char* f : {"a.png", "a.PNG", "a.jpg", "a.JPEG", "a"})
        EXPECT_FALSE(stores_float(f)) << f;
}

TEST(ImageWrite, RoundTripsPngAndExrAndLeavesNoTemporaryFile) {
    TempDir dir;
    const auto px = gradient(16, 8);
    for (const char* name : {"a.png", "a.exr", "a.tif"}) {
        const std::string path = (dir.path / name).string();
        ASSERT_EQ(write_image_atomic(path, {16, 8, px}), "");
        auto in = OIIO::ImageInput::open(path);
        ASSERT_TRUE(in) << name;
        EXPECT_EQ(in->spec().width, 16);
        // The gradient is opaque: PNG stores it as RGB (alpha 1 implied).
        const int channels = std::string(name) == "a.png" ? 3 : 4;
        EXPECT_EQ(in->spec().nchannels, channels);
        std::vector<float> back(px.size(), 1.0f);
        ASSERT_TRUE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, back.data(),
                                   4 * sizeof(float)));
        const float step = std::string(name) == "a.png" ? 0.5f / 255 + 1e-6f : 1e-6f;
        for (std::size_t i = 0; i < px.size(); ++i) ASSERT_NEAR(back[i], px[i], step) << name << i;
    }
    for (const auto& e : fs::directory_iterator(dir.path))
        EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

// The file with the time OpenImageIO stamps into an EXR header (capDate,
// "YYYY:MM:DD hh:mm:ss", the moment it is written) blanked: two writes a
// second apart differ there only (regression: failed under the sanitizers,
// whose writes straddled a second).
std::string without_capture_date(std::string file) {
    const std::string key("capDate\0string\0\x13\0\0\0", 19);
    if (const auto at = file.find(key); at != std::string::npos)
        file.replace(at + key.size(), 19, 19, '-');
    return file;
}

// A Canvas8 is written as the float canvas holding the same values: the
// same file, byte for byte (but for the time of writing), in an 8-bit and a
// float format.
TEST(ImageWrite, ACanvas8WritesAsTheFloatCanvasOfItsValues) {
    TempDir dir;
    const int w = 23, h = 7;
    Canvas8 bytes(w, h);
    Canvas floats(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto a = std::uint8_t((x * 37 + y * 11) % 256);
            const Premul8 p{std::uint8_t(a * x / w), std::uint8_t(a * y / h), std::uint8_t(a / 2),
                            a};
            bytes.row(y)[x] = p;
            floats.row(y)[x] = to_premul(p);
        }
    for (const char* ext : {".png", ".exr"}) {
        const std::string a = (dir.path / (std::string("u8") + ext)).string();
        const std::string b = (dir.path / (std::string("f") + ext)).string();
        ASSERT_EQ(write_canvas_atomic(a, bytes), "");
        ASSERT_EQ(write_canvas_atomic(b, floats), "");
        std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
        const std::string ca{std::istreambuf_iterator<char>(fa), {}};
        const std::string cb{std::istreambuf_iterator<char>(fb), {}};
        EXPECT_FALSE(ca.empty()) << ext;
        EXPECT_TRUE(without_capture_date(ca) == without_capture_date(cb)) << ext;
    }
}

// A premultiplied view (floats, and bytes) is written as each pixel's
// straight color in bytes: channel_to_u8 of straight_of, the scalar formula,
// byte for byte, read back by OIIO's PNG reader (the writer is our libpng
// one); faint, transparent and over-range pixels included.
TEST(ImageWrite, PremultipliedViewsWriteTheStraightBytesOfEachPixel) {
    TempDir dir;
    const int w = 61, h = 5;
    std::vector<float> floats(std::size_t(w * h * 4));
    std::vector<std::uint8_t> bytes(floats.size());
    for (std::size_t i = 0; i < floats.size(); i += 4) {
        const float a = i % 29 == 0 ? 0.0f : float((i * 7919) % 1000) / 999.0f;
        for (std::size_t c = 0; c < 3; ++c)
            floats[i + c] = a * float((i * 31 + c * 17) % 1000) / 999.0f * (c == 2 ? 1.2f : 1.0f);
        floats[i + 3] = a;
        for (std::size_t c = 0; c < 4; ++c) bytes[i + c] = std::uint8_t((i * 13 + c * 71) % 256);
        bytes[i + 3] = std::max({bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]});
    }
    ImageView from_floats{w, h, floats, Alpha::premultiplied};
    ImageView from_bytes{w, h, {}, Alpha::premultiplied};
    from_bytes.rgba8 = bytes;
    for (const auto& [name, view] : {std::pair{"floats", from_floats}, {"bytes", from_bytes}}) {
        const std::string path = (dir.path / (std::string(name) + ".png")).string();
        ASSERT_EQ(write_image_atomic(path, view), "") << name;
        OIIO::ImageSpec config; // the file's own bytes, not premultiplied on reading
        config["oiio:UnassociatedAlpha"] = 1;
        auto in = OIIO::ImageInput::open(path, &config);
        ASSERT_TRUE(in) << name;
        ASSERT_EQ(in->spec().nchannels, 4) << name;
        std::vector<std::uint8_t> back(floats.size());
        const bool in_bytes = view.rgba.empty(); // a structured binding clang 14 cannot capture
        ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, back.data()));
        for (std::size_t i = 0; i < back.size(); i += 4) {
            const auto v = [&, in_bytes](std::size_t c) {
                return in_bytes ? float(bytes[i + c]) / 255.0f : floats[i + c];
            };
            const Rgba s = straight_of({v(0), v(1), v(2), v(3)});
            const std::uint8_t want[4] = {channel_to_u8(s.r), channel_to_u8(s.g),
                                          channel_to_u8(s.b), channel_to_u8(s.a)};
            for (std::size_t c = 0; c < 4; ++c)
                ASSERT_EQ(int(back[i + c]), int(want[c]))
                    << name << " pixel " << i / 4 << " channel " << c;
        }
    }
}

TEST(ImageWrite, FailuresLeaveAnExistingFileIntact) {
    TempDir dir;
    const auto px = gradient(4, 4);
    // The destination is a folder.
    fs::create_directories(dir.path / "folder.png");
    EXPECT_NE(write_image_atomic((dir.path / "folder.png").string(), {4, 4, px}).find("folder"),
              std::string::npos);
    // An unknown extension.
    EXPECT_NE(write_image_atomic((dir.path / "x.nosuchformat").string(), {4, 4, px}), "");
    // An unwritable folder keeps its existing file byte for byte.
    const fs::path sub = dir.path / "locked";
    fs::create_directories(sub);
    const fs::path existing = sub / "keep.png";
    { std::ofstream(existing) << "precious"; }
    fs::permissions(sub, fs::perms::owner_read | fs::perms::owner_exec);
    if (::geteuid() != 0) { // root ignores permissions
        EXPECT_NE(write_image_atomic(existing.string(), {4, 4, px}), "");
        std::ifstream in(existing);
        std::string content;
        in >> content;
        EXPECT_EQ(content, "precious");
    }
}

} // namespace
} // namespace casteljau
