// The pseudo-attributes of a processing instruction's text: an
// xml-stylesheet's href and type (Associating Style Sheets, 3), an XML
// declaration's version and encoding (XML 1.0, 2.8). They have the syntax of
// XML attributes, character and predefined entity references included, so
// pugixml reads them as an element's.
#pragma once

#include <map>
#include <pugixml.hpp>
#include <string>
#include <string_view>

namespace casteljau::svg_detail {

/// The pseudo-attributes in `s`, by name; none when malformed.
inline std::map<std::string, std::string> pseudo_attributes(std::string_view s) {
    std::map<std::string, std::string> out;
    pugi::xml_document d;
    if (!d.load_string(("<x " + std::string(s) + "/>").c_str())) return out;
    for (const pugi::xml_attribute& a : d.first_child().attributes())
        out.emplace(a.name(), a.value());
    return out;
}

} // namespace casteljau::svg_detail
