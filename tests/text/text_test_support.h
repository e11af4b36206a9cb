// Shared by the text library's tests (layout_test.cpp, font_database_test.cpp,
// unicode_test.cpp): the pinned fonts' folders and files, a few words of
// other scripts spelled out in UTF-8, and a font database of the pinned
// fonts only.
#pragma once
#include "casteljau/curve/path.h"
#include "casteljau/text/font_database.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace casteljau::text_test {

inline const std::string kDejaVuDir = "/usr/share/fonts/truetype/dejavu";
inline const std::string kNotoDir = "/usr/share/fonts/truetype/noto";
inline const std::string kDejaVuSans = kDejaVuDir + "/DejaVuSans.ttf";
inline const std::string kNotoDevanagari = kNotoDir + "/NotoSansDevanagari-Regular.ttf";

// UTF-8 spelled out, for readability of the test cases.
inline constexpr const char* kAlefBetGimel = "\xD7\x90\xD7\x91\xD7\x92";   // אבג
inline constexpr const char* kSalam = "\xD8\xB3\xD9\x84\xD8\xA7\xD9\x85";  // سلام
inline constexpr const char* kSamiat = "\xD8\xB3\xD9\x85\xD8\xB9\xD8\xAA"; // سمعت
inline constexpr const char* kNamaste =
    "\xE0\xA4\xA8\xE0\xA4\xAE\xE0\xA4\xB8\xE0\xA5\x8D\xE0\xA4\xA4"
    "\xE0\xA5\x87"; // नमस्ते
inline constexpr const char* kSawasdee =
    "\xE0\xB8\xAA\xE0\xB8\xA7\xE0\xB8\xB1\xE0\xB8\xAA\xE0\xB8\x94"
    "\xE0\xB8\xB5"; // สวัสดี

// DejaVu and Noto, and nothing else: made once (fontconfig scans the
// folders) and shared by the tests that do not change it.
inline FontDatabase& test_fonts() {
    static const std::unique_ptr<FontDatabase> db = [] {
        auto d = FontDatabase::empty();
        EXPECT_TRUE(d->add_font_dir(kDejaVuDir));
        EXPECT_TRUE(d->add_font_dir(kNotoDir));
        return d;
    }();
    return *db;
}

inline FontQuery query(std::string family, int weight = 400, FontStyle style = FontStyle::Normal) {
    FontQuery q;
    q.families = {std::move(family)};
    q.weight = weight;
    q.style = style;
    return q;
}

// The control points of a segment, in order.
inline std::vector<Point> control_points(const Segment& s) {
    return std::visit(
        [](const auto& c) -> std::vector<Point> {
            if constexpr (requires { c.points(); })
                return {c.points().begin(), c.points().end()};
            else
                return {c.p0, c.p1, c.p2};
        },
        s);
}

// The largest distance between corresponding control points of two paths
// of the same structure; infinity when the structure differs.
inline double control_point_distance(const Path& a, const Path& b) {
    if (a.subpaths().size() != b.subpaths().size()) return INFINITY;
    double d = 0;
    for (std::size_t i = 0; i < a.subpaths().size(); ++i) {
        const Subpath &p = a.subpaths()[i], &q = b.subpaths()[i];
        if (p.segments.size() != q.segments.size() || p.closed != q.closed) return INFINITY;
        d = std::max(d, distance(p.start, q.start));
        for (std::size_t k = 0; k < p.segments.size(); ++k) {
            if (p.segments[k].index() != q.segments[k].index()) return INFINITY;
            const std::vector<Point> u = control_points(p.segments[k]),
                                     v = control_points(q.segments[k]);
            for (std::size_t j = 0; j < u.size(); ++j) d = std::max(d, distance(u[j], v[j]));
        }
    }
    return d;
}

} // namespace casteljau::text_test
