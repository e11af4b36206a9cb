// SVGZ (io/gunzip.h): gzip data written by zlib, an encoder other than the
// library's decoder (libdeflate), inflated exactly, within the limit, or
// refused with a reason; an SVGZ document reads as its SVG does.
#include "casteljau/io/gunzip.h"
#include "casteljau/svg/reader.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>
#include <zlib.h>

namespace casteljau {
namespace {

std::vector<unsigned char> gzip(const std::string& text) {
    z_stream z{};
    // 15 + 16: a gzip header and trailer around the deflate data.
    EXPECT_EQ(deflateInit2(&z, 9, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK);
    std::vector<unsigned char> out(deflateBound(&z, uLong(text.size())) + 32);
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
    z.avail_in = uInt(text.size());
    z.next_out = out.data();
    z.avail_out = uInt(out.size());
    EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
    out.resize(z.total_out);
    deflateEnd(&z);
    return out;
}

TEST(Gunzip, InflatesWhatZlibDeflated) {
    std::string text;
    for (int i = 0; i < 5000; ++i) text += "<rect x='" + std::to_string(i) + "'/>\n";
    std::vector<unsigned char> z = gzip(text);
    ASSERT_TRUE(is_gzip(z));
    const Gunzipped g = gunzip(z, 1 << 20);
    EXPECT_EQ(g.error, "");
    EXPECT_TRUE(g.data == text) << g.data.size() << " bytes, not " << text.size();
    // The trailer's size and checksum are checked.
    z[z.size() - 1] ^= 1;
    EXPECT_EQ(gunzip(z, 1 << 20).error, "not valid gzip data");
    EXPECT_FALSE(is_gzip(std::vector<unsigned char>{'<', 's'}));
    // Members one after another are their data one after another (RFC 1952,
    // 2.2); anything else after a member is damage; no room is no data.
    std::vector<unsigned char> two = gzip("<svg>"), second = gzip("</svg>");
    two.insert(two.end(), second.begin(), second.end());
    EXPECT_EQ(gunzip(two, 100).data, "<svg></svg>");
    two.push_back('x');
    EXPECT_EQ(gunzip(two, 100).error, "not valid gzip data");
    EXPECT_EQ(gunzip(second, 0).error, "inflates to more than 0 bytes (the limit)");
}

TEST(Gunzip, ABombStopsAtTheLimitAndDamageIsAnError) {
    const std::vector<unsigned char> bomb = gzip(std::string(std::size_t(8) << 20, ' '));
    EXPECT_LT(bomb.size(), std::size_t(16) << 10) << "8 MiB of one byte";
    EXPECT_EQ(gunzip(bomb, 1 << 20).error, "inflates to more than 1048576 bytes (the limit)");
    std::vector<unsigned char> cut = gzip("<svg width='5' height='5'/>");
    cut.resize(cut.size() / 2);
    EXPECT_EQ(gunzip(cut, 1 << 20).error, "not valid gzip data");
}

TEST(Gunzip, AnSvgzDocumentReadsAsItsSvg) {
    const std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' width='30' height='20'>"
                            "<rect width='10' height='10' fill='red'/></svg>";
    const std::vector<unsigned char> z = gzip(svg);
    const SvgResult plain = parse_svg(svg, "a.svg");
    const SvgResult zipped =
        parse_svg(std::string_view(reinterpret_cast<const char*>(z.data()), z.size()), "a.svgz");
    ASSERT_TRUE(plain.scene && zipped.scene) << zipped.error;
    EXPECT_EQ(zipped.scene->width, 30);
    EXPECT_EQ(zipped.scene->root.children.size(), plain.scene->root.children.size());
    SvgOptions small;
    small.max_file_bytes = 200;
    const std::vector<unsigned char> big = gzip(svg + std::string(2000, ' '));
    const SvgResult over = parse_svg(
        std::string_view(reinterpret_cast<const char*>(big.data()), big.size()), "b.svgz", small);
    EXPECT_EQ(over.error, "b.svgz: gzip data: inflates to more than 200 bytes (the limit)");
}

} // namespace
} // namespace casteljau
