#include "casteljau/svg/font_face.h"

#include "casteljau/io/text_file.h"
#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/detail/reader_impl.h"
#include "casteljau/svg/resource_url.h"
#include "casteljau/svg/style.h"
#include "casteljau/svg/text_properties.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

namespace {

using svg_detail::iequals;
using svg_detail::trim;

// The items of a comma-separated list; commas in quotes or parentheses
// belong to their item.
std::vector<std::string_view> comma_items(std::string_view v) {
    std::vector<std::string_view> out;
    int depth = 0;
    char quote = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (svg_detail::in_css_string(v, i, quote)) continue;
        const char c = v[i];
        if (c == '(') {
            ++depth;
        } else if (c == ')') {
            depth = std::max(0, depth - 1);
        } else if (c == ',' && depth == 0) {
            out.push_back(trim(v.substr(start, i - start)));
            start = i + 1;
        }
    }
    out.push_back(trim(v.substr(start)));
    return out;
}

// The argument of the function `name(` at the start of v, unquoted, and
// what follows its ')'; nullopt when v does not start with it or it is not closed.
std::optional<std::string> function_argument(std::string_view& v, std::string_view name) {
    if (v.size() <= name.size() || !iequals(v.substr(0, name.size()), name) ||
        v[name.size()] != '(')
        return std::nullopt;
    std::string_view rest = trim(v.substr(name.size() + 1));
    std::string arg;
    if (!rest.empty() && (rest[0] == '"' || rest[0] == '\'')) {
        const char quote = rest[0];
        std::size_t i = 1;
        for (; i < rest.size() && rest[i] != quote; ++i) {
            if (rest[i] == '\\' && i + 1 < rest.size()) ++i;
            arg += rest[i];
        }
        if (i >= rest.size()) return std::nullopt;
        rest = trim(rest.substr(i + 1));
        if (rest.empty() || rest[0] != ')') return std::nullopt;
        v = trim(rest.substr(1));
        return arg;
    }
    const std::size_t close = rest.find(')');
    if (close == std::string_view::npos) return std::nullopt;
    arg = std::string(trim(rest.substr(0, close)));
    v = trim(rest.substr(close + 1));
    return arg;
}

// One src item: a url() source, or nullopt for local() and invalid items.
std::optional<FontFaceSource> source(std::string_view item) {
    std::optional<std::string> url = function_argument(item, "url");
    if (!url || url->empty()) return std::nullopt;
    FontFaceSource s{std::move(*url), {}};
    if (const std::optional<std::string> f = function_argument(item, "format")) {
        s.format = *f;
        std::transform(s.format.begin(), s.format.end(), s.format.begin(),
                       [](unsigned char c) { return char(std::tolower(c)); });
    }
    function_argument(item, "tech"); // technologies: what FreeType reads is tried anyway
    if (!item.empty()) return std::nullopt;
    return s;
}

// One weight of a range: font-weight's, but for the relative keywords,
// which a face's descriptor cannot take.
std::optional<int> weight(std::string_view w) {
    if (iequals(w, "bolder") || iequals(w, "lighter")) return std::nullopt;
    return parse_font_weight(w, 400);
}

// font-weight: one weight, two (a range, in either order), or auto (any).
bool weight_range(std::string_view v, FontFaceDescriptors& d) {
    if (iequals(v, "auto")) {
        d.weight_min = 1, d.weight_max = 1000;
        return true;
    }
    const std::size_t gap = v.find_first_of(" \t\n");
    const auto a = weight(v.substr(0, gap));
    const auto b = gap == std::string_view::npos ? a : weight(trim(v.substr(gap)));
    if (!a || !b) return false;
    d.weight_min = std::min(*a, *b), d.weight_max = std::max(*a, *b);
    return true;
}

} // namespace

bool readable_font_format(std::string_view format) {
    for (const char* f :
         {"truetype", "opentype", "woff", "woff2", "collection", "truetype-variations",
          "opentype-variations", "woff-variations", "woff2-variations"})
        if (format == f) return true;
    return false;
}

std::optional<FontFaceRule> parse_font_face(const std::vector<CssDeclaration>& descriptors,
                                            std::string& error) {
    FontFaceRule rule;
    bool family = false, src = false;
    for (const CssDeclaration& d : descriptors) {
        if (d.name == "font-family") {
            const auto names = parse_font_family(d.value);
            family = names && names->size() == 1;
            if (family) rule.descriptors.family = names->front();
        } else if (d.name == "src") {
            rule.sources.clear();
            for (std::string_view item : comma_items(d.value))
                if (auto s = source(item)) rule.sources.push_back(std::move(*s));
            src = !rule.sources.empty() || d.value.find("local(") != std::string::npos;
        } else if (d.name == "font-weight") {
            FontFaceDescriptors w = rule.descriptors;
            if (weight_range(d.value, w)) rule.descriptors = w;
        } else if (d.name == "font-style") {
            const std::string_view s = std::string_view(d.value).substr(0, d.value.find(' '));
            if (iequals(s, "italic"))
                rule.descriptors.style = FontStyle::Italic;
            else if (iequals(s, "oblique"))
                rule.descriptors.style = FontStyle::Oblique;
            else if (iequals(s, "normal") || iequals(s, "auto"))
                rule.descriptors.style = FontStyle::Normal;
        }
    }
    if (!family)
        error = "no valid font-family (one family name)";
    else if (!src)
        error = "no valid src";
    if (!family || !src) return std::nullopt;
    return rule;
}

namespace svg_detail {

// The bytes of a source; nullopt, with `error` set, when they cannot be had.
std::optional<std::vector<unsigned char>> Reader::font_source_bytes(const FontFaceSource& s,
                                                                    std::string& error) {
    if (std::optional<DataUrl> data = parse_data_url(s.url, error)) return std::move(data->bytes);
    if (!error.empty()) return std::nullopt;
    const ResourcePath file =
        resolve_resource_path(s.url, options_.base_dir, options_.resources_dir);
    if (!file.error.empty()) {
        error = file.error;
        return std::nullopt;
    }
    TextFile f = read_text_file(file.path, kMaxFontFileBytes);
    if (!f.error.empty()) {
        error = f.error;
        return std::nullopt;
    }
    return std::vector<unsigned char>(f.text.begin(), f.text.end());
}

// The sheets' @font-face rules from `first` on, of the <style> element `st`:
// each loaded into the document's font layer from its first source that
// loads, or ignored with a warning.
void Reader::load_font_faces(const pugi::xml_node& st, std::size_t first) {
    const std::vector<CssFontFace>& rules = sheet_.font_faces();
    for (std::size_t i = first; i < rules.size(); ++i) {
        // A problem (strictly read, the error: as an <image> that does not load).
        const auto warn_rule = [&](const std::string& what) {
            SvgDiagnostic d = located(st, "style sheet: @font-face: " + what);
            d.line += rules[i].line - 1;
            problem_at(std::move(d));
        };
        std::string error;
        const std::optional<FontFaceRule> rule = parse_font_face(rules[i].descriptors, error);
        if (!rule) {
            warn_rule(error + "; ignored");
            continue;
        }
        if (font_faces_ >= kMaxFontFaces) {
            warn_rule("more than " + std::to_string(kMaxFontFaces) +
                      " fonts in one document (the limit); ignored");
            continue;
        }
        if (!document_fonts_) document_fonts_ = FontDatabase::layer(fonts());
        bool loaded = false; // else `error` says why the last source tried failed
        for (const FontFaceSource& s : rule->sources) {
            if (!s.format.empty() && !readable_font_format(s.format)) continue;
            error.clear();
            std::optional<std::vector<unsigned char>> bytes = font_source_bytes(s, error);
            ++font_faces_;
            if (bytes) {
                auto data = std::make_shared<const std::vector<unsigned char>>(std::move(*bytes));
                loaded = document_fonts_->add_font_data(rule->descriptors, std::move(data), error);
            }
            if (loaded || font_faces_ >= kMaxFontFaces) break;
        }
        if (!loaded)
            warn_rule("no source of '" + rule->descriptors.family + "' loads" +
                      (error.empty() ? std::string() : " (" + error + ")") +
                      "; its text takes the next family");
    }
}

} // namespace svg_detail

} // namespace casteljau
