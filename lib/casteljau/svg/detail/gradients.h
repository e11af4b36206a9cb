// Internal to the SVG reader (not installed): gradient elements -> Gradient.
//
// Every element with an id is indexed once, so gradients may be defined
// anywhere in the document. A reference resolves along the href chain
// (href or xlink:href, SVG 1.1 13.2.2 and 13.2.3): each attribute comes from
// the first gradient of the chain that has it, the stops from the first that
// has any. The chain stops at a missing id (with a warning); a cycle or more
// than kMaxHrefChain links is an error. Stops (13.2.4): offsets are numbers or percentages,
// clamped to [0, 1] and made nondecreasing; stop-color and stop-opacity come
// from attributes or the style attribute.
#pragma once

#include "casteljau/paint/gradient.h"

#include <map>
#include <memory>
#include <pugixml.hpp>
#include <string>

namespace casteljau::svg_detail {

inline constexpr int kMaxHrefChain = 64;

struct GradientRef {
    std::shared_ptr<const Gradient> gradient; // null: not a gradient, or unusable
    std::string warning;                      // why, when null or when the chain was cut
    std::string error;                        // a malformed value: the reader fails
    pugi::xml_node where;                     // the element the message is about
};

class GradientIndex {
  public:
    // `viewport` sizes resolve percentages of userSpaceOnUse gradients.
    GradientIndex(const pugi::xml_node& root, double viewport_w, double viewport_h);
    GradientRef resolve(const std::string& id);

  private:
    GradientRef build(pugi::xml_node node);
    std::map<std::string, pugi::xml_node> by_id_;
    std::map<std::string, GradientRef> cache_;
    double vw_, vh_;
};

} // namespace casteljau::svg_detail
