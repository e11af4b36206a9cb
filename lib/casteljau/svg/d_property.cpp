// A path's geometry (SVG 2, 9.3.1): the d attribute, a presentation
// attribute of the CSS d property, which a style sheet or a style attribute
// may set as `none` or path(<string>). Where CSS declares it, the cascade
// decides (the last valid declaration); an invalid CSS value, path data in
// error included, is ignored with a warning, as CSS drops a declaration it
// cannot parse. The attribute's path data is drawn up to its first error
// (SVG 2, 9.5.4), with a warning.
#include "casteljau/curve/path_data.h"
#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/detail/reader_impl.h"

namespace casteljau::svg_detail {

namespace {

// path("...") or path('...'): the string's text; "" for none; nullopt
// when the value is neither.
std::optional<std::string_view> css_path_string(std::string_view v) {
    v = trim(v);
    if (v == "none") return std::string_view();
    if (v.size() < 8 || !iequals(v.substr(0, 5), "path(") || v.back() != ')') return std::nullopt;
    const std::string_view s = trim(v.substr(5, v.size() - 6));
    if (s.size() < 2 || (s.front() != '"' && s.front() != '\'') || s.back() != s.front())
        return std::nullopt;
    return s.substr(1, s.size() - 2);
}

} // namespace

Path Reader::path_data(const pugi::xml_node& n) {
    // A copy: a style attribute's declarations live only as long as cascade().
    std::string d = n.attribute("d").value();
    bool from_css = false;
    if (in_css(n, "d"))
        cascade(n, false, [&](std::string_view name, std::string_view v, const char* from) {
            if (name != "d") return;
            if (!*from) {
                d = v, from_css = false;
                return;
            }
            const std::optional<std::string_view> s = css_path_string(v);
            if (s && !parse_path_data(*s).error) {
                d = *s, from_css = true;
                return;
            }
            problem(n, std::string(from) + "property d: '" + std::string(v) +
                           "' is not none or path() of valid path data; ignored");
        });
    PathDataResult r = parse_path_data(d);
    if (r.error && !from_css)
        problem(n, "attribute d: path data: at offset " + std::to_string(r.error->offset) + ": " +
                       r.error->message + " (drawn up to there)");
    return std::move(r.path);
}

} // namespace casteljau::svg_detail
