#include "casteljau/svg/detail/xml_namespaces.h"

#include "casteljau/svg/detail/ascii.h"

#include <string>
#include <utility>
#include <vector>

namespace casteljau::svg_detail {

namespace {

constexpr std::string_view kSvg = "http://www.w3.org/2000/svg";
constexpr std::string_view kXlink = "http://www.w3.org/1999/xlink";

// The prefix and the local part of a qualified name ("" and the name when
// it has no prefix).
std::pair<std::string_view, std::string_view> split(std::string_view qname) {
    const std::size_t colon = qname.find(':');
    if (colon == std::string_view::npos) return {{}, qname};
    return {qname.substr(0, colon), qname.substr(colon + 1)};
}

// Walks the elements in document order, keeping the prefixes in scope.
class Renamer : public pugi::xml_tree_walker {
  public:
    bool for_each(pugi::xml_node& n) override {
        if (n.type() != pugi::node_element) return true;
        const int d = depth();
        while (!scope_.empty() && scope_.back().depth >= d) scope_.pop_back();
        for (const pugi::xml_attribute& a : n.attributes()) {
            const auto [prefix, local] = split(a.name());
            if (prefix == "xmlns") scope_.push_back({d, std::string(local), a.value()});
            if (prefix.empty() && local == "xmlns") scope_.push_back({d, "", a.value()});
        }
        const auto [prefix, local] = split(n.name());
        if (!prefix.empty() && uri(prefix) == kSvg) rename(n, local);
        // An unprefixed element under a default namespace other than SVG's
        // (<g xmlns="urn:x"><circle/>): foreign, so it takes a prefix,
        // which the reader skips as it skips i:rect. Undeclared, the
        // default is SVG's (a file without xmlns, as librsvg reads it).
        if (prefix.empty()) {
            const std::string_view* default_uri = declared("");
            if (default_uri && *default_uri != kSvg) rename(n, "foreign:" + std::string(local));
        }
        for (pugi::xml_attribute a : n.attributes()) {
            const auto [p, l] = split(a.name());
            if (p.empty() || p == "xmlns" || p == "xml") continue;
            // svg:fill is not fill (SVG's attributes are in no namespace),
            // so only XLink's are renamed.
            if (p != "xlink" && uri(p) == kXlink) a.set_name(("xlink:" + std::string(l)).c_str());
        }
        return true;
    }

    RenamedElements renamed;

  private:
    void rename(pugi::xml_node& n, std::string_view to) {
        renamed.try_emplace(n.internal_object(), RenamedElement{n.name(), n.offset_debug()});
        n.set_name(std::string(to).c_str());
    }
    // The namespace the nearest declaration of `prefix` ("": the default)
    // gives it, or null when none is in scope.
    const std::string_view* declared(std::string_view prefix) const {
        for (auto it = scope_.rbegin(); it != scope_.rend(); ++it)
            if (it->prefix == prefix) return &it->uri;
        return nullptr;
    }
    std::string_view uri(std::string_view prefix) const {
        const std::string_view* u = declared(prefix);
        return u ? *u : std::string_view();
    }
    struct Binding {
        int depth;
        std::string prefix;
        std::string_view uri;
    };
    std::vector<Binding> scope_;
};

} // namespace

bool declares_own_prefixes(std::string_view text) {
    for (std::size_t i = text.find("xmlns"); i != std::string_view::npos;
         i = text.find("xmlns", i + 5)) {
        // xmlns:PREFIX = "URI" or xmlns = "URI", spaces allowed around '=';
        // anything else (a comment's words, a broken attribute) is passed over.
        std::size_t k = i + 5;
        const bool has_prefix = k < text.size() && text[k] == ':';
        while (k < text.size() && text[k] != '=' && text[k] != '>' && text[k] != '"' &&
               text[k] != '\'')
            ++k;
        if (k >= text.size() || text[k] != '=') continue;
        const std::string_view prefix = has_prefix ? trim(text.substr(i + 6, k - i - 6)) : "";
        if (!has_prefix && !trim(text.substr(i + 5, k - i - 5)).empty()) continue; // xmlnsfoo=
        ++k;
        while (k < text.size() && is_xml_space(text[k])) ++k;
        if (k >= text.size() || (text[k] != '"' && text[k] != '\'')) continue;
        const std::size_t end = text.find(text[k], k + 1);
        if (end == std::string_view::npos) return false;
        const std::string_view uri = text.substr(k + 1, end - k - 1);
        if (!has_prefix
                ? uri != kSvg
                : (uri == kSvg && prefix != "svg") || (uri == kXlink && prefix != "xlink") ||
                      (uri == kSvg && text.find("<svg:") != std::string_view::npos))
            return true;
    }
    return false;
}

RenamedElements normalize_namespaces(pugi::xml_document& doc) {
    Renamer r;
    doc.traverse(r);
    return std::move(r.renamed);
}

} // namespace casteljau::svg_detail
