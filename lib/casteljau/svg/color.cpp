#include "casteljau/svg/color.h"

#include "casteljau/svg/color_spaces.h"
#include "casteljau/svg/detail/ascii.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace casteljau {

namespace {

struct Named {
    const char* name;
    unsigned char r, g, b;
};

// SVG 1.1 section 4.4, "Recognized color keyword names", sorted by name (the
// spec's own list is not: "grey" precedes "green") for binary search.
// clang-format off
constexpr std::array<Named, 147> kNamed = {{
    {"aliceblue", 240, 248, 255},
    {"antiquewhite", 250, 235, 215},
    {"aqua", 0, 255, 255},
    {"aquamarine", 127, 255, 212},
    {"azure", 240, 255, 255},
    {"beige", 245, 245, 220},
    {"bisque", 255, 228, 196},
    {"black", 0, 0, 0},
    {"blanchedalmond", 255, 235, 205},
    {"blue", 0, 0, 255},
    {"blueviolet", 138, 43, 226},
    {"brown", 165, 42, 42},
    {"burlywood", 222, 184, 135},
    {"cadetblue", 95, 158, 160},
    {"chartreuse", 127, 255, 0},
    {"chocolate", 210, 105, 30},
    {"coral", 255, 127, 80},
    {"cornflowerblue", 100, 149, 237},
    {"cornsilk", 255, 248, 220},
    {"crimson", 220, 20, 60},
    {"cyan", 0, 255, 255},
    {"darkblue", 0, 0, 139},
    {"darkcyan", 0, 139, 139},
    {"darkgoldenrod", 184, 134, 11},
    {"darkgray", 169, 169, 169},
    {"darkgreen", 0, 100, 0},
    {"darkgrey", 169, 169, 169},
    {"darkkhaki", 189, 183, 107},
    {"darkmagenta", 139, 0, 139},
    {"darkolivegreen", 85, 107, 47},
    {"darkorange", 255, 140, 0},
    {"darkorchid", 153, 50, 204},
    {"darkred", 139, 0, 0},
    {"darksalmon", 233, 150, 122},
    {"darkseagreen", 143, 188, 143},
    {"darkslateblue", 72, 61, 139},
    {"darkslategray", 47, 79, 79},
    {"darkslategrey", 47, 79, 79},
    {"darkturquoise", 0, 206, 209},
    {"darkviolet", 148, 0, 211},
    {"deeppink", 255, 20, 147},
    {"deepskyblue", 0, 191, 255},
    {"dimgray", 105, 105, 105},
    {"dimgrey", 105, 105, 105},
    {"dodgerblue", 30, 144, 255},
    {"firebrick", 178, 34, 34},
    {"floralwhite", 255, 250, 240},
    {"forestgreen", 34, 139, 34},
    {"fuchsia", 255, 0, 255},
    {"gainsboro", 220, 220, 220},
    {"ghostwhite", 248, 248, 255},
    {"gold", 255, 215, 0},
    {"goldenrod", 218, 165, 32},
    {"gray", 128, 128, 128},
    {"green", 0, 128, 0},
    {"greenyellow", 173, 255, 47},
    {"grey", 128, 128, 128},
    {"honeydew", 240, 255, 240},
    {"hotpink", 255, 105, 180},
    {"indianred", 205, 92, 92},
    {"indigo", 75, 0, 130},
    {"ivory", 255, 255, 240},
    {"khaki", 240, 230, 140},
    {"lavender", 230, 230, 250},
    {"lavenderblush", 255, 240, 245},
    {"lawngreen", 124, 252, 0},
    {"lemonchiffon", 255, 250, 205},
    {"lightblue", 173, 216, 230},
    {"lightcoral", 240, 128, 128},
    {"lightcyan", 224, 255, 255},
    {"lightgoldenrodyellow", 250, 250, 210},
    {"lightgray", 211, 211, 211},
    {"lightgreen", 144, 238, 144},
    {"lightgrey", 211, 211, 211},
    {"lightpink", 255, 182, 193},
    {"lightsalmon", 255, 160, 122},
    {"lightseagreen", 32, 178, 170},
    {"lightskyblue", 135, 206, 250},
    {"lightslategray", 119, 136, 153},
    {"lightslategrey", 119, 136, 153},
    {"lightsteelblue", 176, 196, 222},
    {"lightyellow", 255, 255, 224},
    {"lime", 0, 255, 0},
    {"limegreen", 50, 205, 50},
    {"linen", 250, 240, 230},
    {"magenta", 255, 0, 255},
    {"maroon", 128, 0, 0},
    {"mediumaquamarine", 102, 205, 170},
    {"mediumblue", 0, 0, 205},
    {"mediumorchid", 186, 85, 211},
    {"mediumpurple", 147, 112, 219},
    {"mediumseagreen", 60, 179, 113},
    {"mediumslateblue", 123, 104, 238},
    {"mediumspringgreen", 0, 250, 154},
    {"mediumturquoise", 72, 209, 204},
    {"mediumvioletred", 199, 21, 133},
    {"midnightblue", 25, 25, 112},
    {"mintcream", 245, 255, 250},
    {"mistyrose", 255, 228, 225},
    {"moccasin", 255, 228, 181},
    {"navajowhite", 255, 222, 173},
    {"navy", 0, 0, 128},
    {"oldlace", 253, 245, 230},
    {"olive", 128, 128, 0},
    {"olivedrab", 107, 142, 35},
    {"orange", 255, 165, 0},
    {"orangered", 255, 69, 0},
    {"orchid", 218, 112, 214},
    {"palegoldenrod", 238, 232, 170},
    {"palegreen", 152, 251, 152},
    {"paleturquoise", 175, 238, 238},
    {"palevioletred", 219, 112, 147},
    {"papayawhip", 255, 239, 213},
    {"peachpuff", 255, 218, 185},
    {"peru", 205, 133, 63},
    {"pink", 255, 192, 203},
    {"plum", 221, 160, 221},
    {"powderblue", 176, 224, 230},
    {"purple", 128, 0, 128},
    {"red", 255, 0, 0},
    {"rosybrown", 188, 143, 143},
    {"royalblue", 65, 105, 225},
    {"saddlebrown", 139, 69, 19},
    {"salmon", 250, 128, 114},
    {"sandybrown", 244, 164, 96},
    {"seagreen", 46, 139, 87},
    {"seashell", 255, 245, 238},
    {"sienna", 160, 82, 45},
    {"silver", 192, 192, 192},
    {"skyblue", 135, 206, 235},
    {"slateblue", 106, 90, 205},
    {"slategray", 112, 128, 144},
    {"slategrey", 112, 128, 144},
    {"snow", 255, 250, 250},
    {"springgreen", 0, 255, 127},
    {"steelblue", 70, 130, 180},
    {"tan", 210, 180, 140},
    {"teal", 0, 128, 128},
    {"thistle", 216, 191, 216},
    {"tomato", 255, 99, 71},
    {"turquoise", 64, 224, 208},
    {"violet", 238, 130, 238},
    {"wheat", 245, 222, 179},
    {"white", 255, 255, 255},
    {"whitesmoke", 245, 245, 245},
    {"yellow", 255, 255, 0},
    {"yellowgreen", 154, 205, 50}
}};
// clang-format on

constexpr bool sorted_by_name() {
    for (std::size_t i = 1; i < kNamed.size(); ++i)
        if (!(std::string_view(kNamed[i - 1].name) < std::string_view(kNamed[i].name)))
            return false;
    return true;
}
static_assert(sorted_by_name(), "kNamed must be sorted for std::lower_bound");

using svg_detail::trim;

int hex(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// #rgb, #rgba, #rrggbb, #rrggbbaa (CSS Color 4, 5.2): a short form's digit d
// stands for dd, that is d * 17.
std::optional<Rgba> parse_hex(std::string_view h) {
    if (h.size() != 3 && h.size() != 4 && h.size() != 6 && h.size() != 8) return std::nullopt;
    int v[8];
    for (std::size_t i = 0; i < h.size(); ++i)
        if ((v[i] = hex(h[i])) < 0) return std::nullopt;
    const bool shorthand = h.size() <= 4;
    float c[4] = {0, 0, 0, 1};
    for (std::size_t k = 0; k < h.size() / (shorthand ? 1 : 2); ++k)
        c[k] = float(shorthand ? v[k] * 17 : v[2 * k] * 16 + v[2 * k + 1]) / 255.0f;
    return Rgba{c[0], c[1], c[2], c[3]};
}

// One argument of a color function: a number, with '%' or an angle unit
// (deg, grad, rad, turn) after it, or the keyword none (modern syntax only).
struct Arg {
    double value = 0;
    std::string_view unit; // "", "%", or an angle unit
    bool none = false;
};

std::optional<Arg> parse_arg(std::string_view t) {
    if (t == "none") return Arg{0, {}, true};
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    Arg a;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), a.value);
    if (ec != std::errc() || !std::isfinite(a.value)) return std::nullopt;
    a.unit = t.substr(std::size_t(end - t.data()));
    if (a.unit.empty() || a.unit == "%" || a.unit == "deg" || a.unit == "grad" || a.unit == "rad" ||
        a.unit == "turn")
        return a;
    return std::nullopt;
}

// The arguments of rgb() or hsl() (CSS Color 4, 5.1 and 7.1): the legacy form
// "a, b, c[, alpha]" (commas; no none) or the modern "a b c[ / alpha]".
struct Args {
    std::vector<Arg> v;
    bool legacy = false;
};

bool space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

std::optional<Args> split_args(std::string_view s) {
    Args out;
    out.legacy = s.find(',') != s.npos;
    std::vector<std::string_view> tokens;
    std::size_t slash_after = 0; // tokens before the slash, 0 when none
    if (out.legacy) {
        for (std::size_t start = 0; start <= s.size();) {
            const std::size_t comma = std::min(s.find(',', start), s.size());
            tokens.push_back(trim(s.substr(start, comma - start)));
            start = comma + 1;
        }
    } else {
        std::size_t i = 0;
        while (i < s.size()) {
            if (space(s[i])) {
                ++i;
            } else if (s[i] == '/') {
                if (slash_after || tokens.size() != 3) return std::nullopt;
                slash_after = tokens.size(), ++i;
            } else {
                const std::size_t start = i;
                while (i < s.size() && !space(s[i]) && s[i] != '/') ++i;
                tokens.push_back(s.substr(start, i - start));
            }
        }
        if (tokens.size() != (slash_after ? 4u : 3u)) return std::nullopt;
    }
    if (tokens.size() < 3 || tokens.size() > 4) return std::nullopt;
    for (const std::string_view t : tokens) {
        const auto a = parse_arg(t); // a legacy token with a space in it fails here
        if (!a || (out.legacy && a->none)) return std::nullopt;
        out.v.push_back(*a);
    }
    return out;
}

// An alpha value: a number or a percentage, clamped to [0, 1]; none is 0.
std::optional<float> alpha_of(const std::vector<Arg>& args) {
    if (args.size() < 4) return 1.0f;
    const Arg& a = args[3];
    if (!a.unit.empty() && a.unit != "%") return std::nullopt;
    return float(std::clamp(a.unit == "%" ? a.value / 100 : a.value, 0.0, 1.0));
}

// rgb() and rgba(): numbers in [0, 255] or percentages, clamped. The legacy
// form takes all three of one kind; the modern form may mix them.
std::optional<Rgba> parse_rgb(std::string_view inside) {
    const auto args = split_args(inside);
    if (!args) return std::nullopt;
    const auto alpha = alpha_of(args->v);
    float c[3];
    for (int i = 0; i < 3; ++i) {
        const Arg& a = args->v[std::size_t(i)];
        const bool percent = a.unit == "%";
        if ((!percent && !a.unit.empty()) || (args->legacy && percent != (args->v[0].unit == "%")))
            return std::nullopt;
        c[i] = float(std::clamp(percent ? a.value / 100 : a.value / 255, 0.0, 1.0));
    }
    if (!alpha) return std::nullopt;
    return Rgba{c[0], c[1], c[2], *alpha};
}

// A hue in degrees: a number, or an angle in deg, grad, rad or turn.
std::optional<double> hue_degrees(const Arg& h) {
    if (h.unit.empty() || h.unit == "deg") return h.value;
    if (h.unit == "grad") return h.value * 0.9;
    if (h.unit == "rad") return h.value * 180 / std::numbers::pi;
    if (h.unit == "turn") return h.value * 360;
    return std::nullopt;
}

// CSS Color 4's hsl-to-rgb (7.1), s and l in [0, 1].
Rgba hsl_to_rgb(double deg, double s, double l, float alpha) {
    const double hue = std::fmod(std::fmod(deg, 360) + 360, 360);
    const auto f = [&](double n) {
        const double k = std::fmod(n + hue / 30, 12);
        const double a = s * std::min(l, 1 - l);
        return float(l - a * std::max(-1.0, std::min({k - 3, 9 - k, 1.0})));
    };
    return Rgba{f(0), f(8), f(4), alpha};
}

// hsl() and hsla() (CSS Color 4, 7): the hue in degrees (a number or an
// angle), saturation and lightness as percentages (the modern form also takes
// numbers, as percentages without the sign), then the spec's hsl-to-rgb.
std::optional<Rgba> parse_hsl(std::string_view inside) {
    const auto args = split_args(inside);
    if (!args) return std::nullopt;
    const auto alpha = alpha_of(args->v);
    const std::optional<double> deg = hue_degrees(args->v[0]);
    if (!deg) return std::nullopt;
    double sl[2];
    for (int i = 0; i < 2; ++i) {
        const Arg& a = args->v[std::size_t(i) + 1];
        if (a.unit != "%" && (args->legacy || !a.unit.empty())) return std::nullopt;
        sl[i] = std::clamp(a.value / 100, 0.0, 1.0);
    }
    if (!alpha) return std::nullopt;
    return hsl_to_rgb(*deg, sl[0], sl[1], *alpha);
}

// hwb() (CSS Color 4, 8): hue, whiteness, blackness (percentages, or numbers
// as percentages), modern form only; whiteness and blackness adding up past
// 100% make a gray of their ratio.
std::optional<Rgba> parse_hwb(std::string_view inside) {
    const auto args = split_args(inside);
    if (!args || args->legacy) return std::nullopt;
    const auto alpha = alpha_of(args->v);
    const std::optional<double> deg = hue_degrees(args->v[0]);
    double wb[2];
    for (int i = 0; i < 2; ++i) {
        const Arg& a = args->v[std::size_t(i) + 1];
        if (!a.unit.empty() && a.unit != "%") return std::nullopt;
        wb[i] = std::clamp(a.value / 100, 0.0, 1.0);
    }
    if (!alpha || !deg) return std::nullopt;
    if (wb[0] + wb[1] >= 1) {
        const float gray = float(wb[0] / (wb[0] + wb[1]));
        return Rgba{gray, gray, gray, *alpha};
    }
    const Rgba pure = hsl_to_rgb(*deg, 1, 0.5, 1);
    const auto mix = [&](float c) { return float(c * (1 - wb[0] - wb[1]) + wb[0]); };
    return Rgba{mix(pure.r), mix(pure.g), mix(pure.b), *alpha};
}

// lab(), lch(), oklab() and oklch() (CSS Color 4, 9 and 10; conversions in
// color_spaces.h), modern form only: lightness a number or a percentage of
// `l_full`, a/b or chroma numbers or percentages of `ab_full` (chroma not
// below 0), the hue an angle.
std::optional<Rgba> parse_lab_family(std::string_view inside, bool polar, bool ok) {
    const auto args = split_args(inside);
    if (!args || args->legacy) return std::nullopt;
    const auto alpha = alpha_of(args->v);
    const double l_full = ok ? 1 : 100, ab_full = ok ? 0.4 : polar ? 150 : 125;
    const auto scaled = [&](const Arg& a, double full) -> std::optional<double> {
        if (a.unit == "%") return a.value / 100 * full;
        if (!a.unit.empty()) return std::nullopt;
        return a.value;
    };
    const std::optional<double> l = scaled(args->v[0], l_full);
    std::optional<double> a = scaled(args->v[1], ab_full);
    std::optional<double> b;
    if (polar) {
        const std::optional<double> deg = hue_degrees(args->v[2]);
        if (deg && a) {
            const double c = std::max(*a, 0.0), h = *deg * std::numbers::pi / 180;
            b = c * std::sin(h), a = c * std::cos(h);
        }
    } else {
        b = scaled(args->v[2], ab_full);
    }
    if (!alpha || !l || !a || !b) return std::nullopt;
    const double lc = std::clamp(*l, 0.0, l_full);
    return ok ? oklab_to_srgb(lc, *a, *b, *alpha) : lab_to_srgb(lc, *a, *b, *alpha);
}

// "name(" ... ")" of a functional notation, the inside; nullopt otherwise.
std::optional<std::string_view> function_args(std::string_view s, std::string_view name) {
    if (s.size() < name.size() + 2 || s.substr(0, name.size()) != name || s[name.size()] != '(' ||
        s.back() != ')')
        return std::nullopt;
    return s.substr(name.size() + 1, s.size() - name.size() - 2);
}

} // namespace

std::optional<Rgba> parse_color(std::string_view text) {
    text = trim(text);
    // SVG 1.1 (4.2) lets an ICC color follow an sRGB one: the sRGB one is used.
    if (const std::size_t icc = text.find("icc-color("); icc != text.npos && icc > 0)
        text = trim(text.substr(0, icc));
    if (text.empty()) return std::nullopt;
    if (text.front() == '#') return parse_hex(text.substr(1));
    std::string lower(text);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    for (const char* f : {"rgb", "rgba"})
        if (const auto inside = function_args(lower, f)) return parse_rgb(trim(*inside));
    for (const char* f : {"hsl", "hsla"})
        if (const auto inside = function_args(lower, f)) return parse_hsl(trim(*inside));
    if (const auto inside = function_args(lower, "hwb")) return parse_hwb(trim(*inside));
    for (const bool ok : {false, true})
        for (const bool polar : {false, true})
            if (const auto inside = function_args(lower, ok ? (polar ? "oklch" : "oklab")
                                                            : (polar ? "lch" : "lab")))
                return parse_lab_family(trim(*inside), polar, ok);
    if (lower == "transparent") return Rgba{0, 0, 0, 0};
    const auto it = std::lower_bound(
        kNamed.begin(), kNamed.end(), lower,
        [](const Named& n, const std::string& k) { return k.compare(n.name) > 0; });
    if (it == kNamed.end() || lower != it->name) return std::nullopt;
    return Rgba{it->r / 255.0f, it->g / 255.0f, it->b / 255.0f, 1};
}

} // namespace casteljau
