// Internal to the SVG reader (not installed): a pugixml document as the
// element tree that style sheets match against (CssTree). Nodes are
// pugixml's own node pointers, so converting either way costs nothing.
#pragma once

#include "casteljau/svg/css.h"

#include <cctype>
#include <pugixml.hpp>

namespace casteljau::svg_detail {

class PugiCssTree final : public CssTree {
  public:
    static Node node(const pugi::xml_node& n) { return n.internal_object(); }
    static pugi::xml_node xml(Node n) {
        return pugi::xml_node(static_cast<pugi::xml_node_struct*>(const_cast<void*>(n)));
    }

    std::string_view name(Node e) const override { return xml(e).name(); }
    const char* attribute(Node e, const char* name) const override {
        const pugi::xml_attribute a = xml(e).attribute(name);
        return a ? a.value() : nullptr;
    }
    // The document node above the root element is not an element.
    Node parent(Node e) const override { return element(xml(e).parent()); }
    Node first_child(Node e) const override { return forward(xml(e).first_child()); }
    Node next_sibling(Node e) const override { return forward(xml(e).next_sibling()); }
    Node previous_sibling(Node e) const override {
        pugi::xml_node n = xml(e).previous_sibling();
        while (n && n.type() != pugi::node_element) n = n.previous_sibling();
        return element(n);
    }
    // Comments and processing instructions do not count (Selectors 4, 14.2);
    // whitespace-only text does not either, as Selectors 4 now says.
    bool empty(Node e) const override {
        for (const pugi::xml_node& c : xml(e).children()) {
            if (c.type() == pugi::node_element) return false;
            if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata)
                for (const char* p = c.value(); *p; ++p)
                    if (!std::isspace(static_cast<unsigned char>(*p))) return false;
        }
        return true;
    }

  private:
    static Node element(const pugi::xml_node& n) {
        return n.type() == pugi::node_element ? node(n) : nullptr;
    }
    static Node forward(pugi::xml_node n) {
        while (n && n.type() != pugi::node_element) n = n.next_sibling();
        return element(n);
    }
};

} // namespace casteljau::svg_detail
