#include "casteljau/svg/detail/xml_namespaces.h"

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
        }
        const auto [prefix, local] = split(n.name());
        if (!prefix.empty() && uri(prefix) == kSvg) n.set_name(std::string(local).c_str());
        for (pugi::xml_attribute a : n.attributes()) {
            const auto [p, l] = split(a.name());
            if (p.empty() || p == "xmlns" || p == "xml") continue;
            const std::string_view u = uri(p);
            if (u == kXlink && p != "xlink")
                a.set_name(("xlink:" + std::string(l)).c_str());
            else if (u == kSvg) // an attribute in the SVG namespace is the plain one
                a.set_name(std::string(l).c_str());
        }
        return true;
    }

  private:
    std::string_view uri(std::string_view prefix) const {
        for (auto it = scope_.rbegin(); it != scope_.rend(); ++it)
            if (it->prefix == prefix) return it->uri;
        return {};
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
    for (std::size_t i = text.find("xmlns:"); i != std::string_view::npos;
         i = text.find("xmlns:", i + 6)) {
        const std::size_t eq = text.find('=', i);
        if (eq == std::string_view::npos) return false;
        std::string_view prefix = text.substr(i + 6, eq - i - 6);
        while (!prefix.empty() && (prefix.back() == ' ' || prefix.back() == '\t' ||
                                   prefix.back() == '\n' || prefix.back() == '\r'))
            prefix.remove_suffix(1);
        const std::size_t q = text.find_first_of("\"'", eq);
        if (q == std::string_view::npos) return false;
        const std::size_t end = text.find(text[q], q + 1);
        if (end == std::string_view::npos) return false;
        const std::string_view uri = text.substr(q + 1, end - q - 1);
        if (uri == kSvg || (uri == kXlink && prefix != "xlink")) return true;
    }
    return false;
}

void normalize_namespaces(pugi::xml_document& doc) {
    Renamer r;
    doc.traverse(r);
}

} // namespace casteljau::svg_detail
