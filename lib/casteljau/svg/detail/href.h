// Internal to the SVG reader (not installed): href links between elements.
#pragma once

#include "casteljau/svg/detail/ascii.h"

#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau::svg_detail {

/// Links followed at most along an href chain (gradients, patterns).
inline constexpr int kMaxHrefChain = 64;

/// The element's href (SVG 2) or, without one, its xlink:href (SVG 1.1); ""
/// when it has neither.
inline const char* href_of(const pugi::xml_node& n) {
    if (const pugi::xml_attribute a = n.attribute("href")) return a.value();
    return n.attribute("xlink:href").value();
}

/// A <use>'s href, the spaces around it dropped (as URL parsing drops them):
/// what use() draws and what the expansion bound counts must agree.
inline std::string_view use_href(const pugi::xml_node& n) { return trim(href_of(n)); }

/// The chain of elements from `start` along their hrefs (a paint server
/// inherits what it lacks from the next, SVG 1.1 13.2.2 and 13.3), each one
/// `is_kind` accepts (`kind` names them in messages): cut at a target that
/// is missing or of another kind, at a link that would close a cycle and
/// after kMaxHrefChain links, each told to `problem(element, message)`;
/// `find(id)` looks an id up.
template <class Find, class IsKind, class Problem>
std::vector<pugi::xml_node> href_chain(const pugi::xml_node& start, const char* kind,
                                       const Find& find, const IsKind& is_kind,
                                       const Problem& problem) {
    std::vector<pugi::xml_node> chain{start};
    for (const char* href = href_of(start); *href; href = href_of(chain.back())) {
        const pugi::xml_node next = href[0] == '#' ? find(href + 1) : pugi::xml_node();
        if (!next || !is_kind(next)) {
            problem(chain.back(),
                    std::string("href '") + href + "' names no " + kind + "; ignored");
            break;
        }
        for (const pugi::xml_node& n : chain)
            if (n == next) {
                problem(chain.back(),
                        std::string("href '") + href + "' makes a cycle; the chain ends here");
                return chain;
            }
        if (int(chain.size()) >= kMaxHrefChain) {
            problem(chain.back(), "the href chain is longer than " + std::to_string(kMaxHrefChain) +
                                      " links (the limit); it ends here");
            break;
        }
        chain.push_back(next);
    }
    return chain;
}

/// Attribute `name` of the first element of `chain` that has it (the chain
/// inherits what it lacks), or a null attribute when none has it.
inline pugi::xml_attribute chain_attribute(const std::vector<pugi::xml_node>& chain,
                                           const char* name) {
    for (const pugi::xml_node& e : chain)
        if (const pugi::xml_attribute a = e.attribute(name)) return a;
    return pugi::xml_attribute();
}

} // namespace casteljau::svg_detail
