// Internal to the SVG reader (not installed): gradient elements -> Gradient.
//
// Every element with an id is indexed once, so gradients may be defined
// anywhere in the document. A reference resolves along the href chain
// (href or xlink:href, SVG 1.1 13.2.2 and 13.2.3): each attribute comes from
// the first gradient of the chain that has it, the stops from the first that
// has any. The chain stops at a missing id, at a link that would close a
// cycle and after kMaxHrefChain links: the gradient uses what it has. Stops
// (13.2.4): offsets are numbers or percentages, clamped to [0, 1] and made
// nondecreasing; stop-color and stop-opacity come from attributes or the
// style attribute. An invalid value (an attribute, a stop's) is a problem
// and takes its initial value, as CSS error handling says.
#pragma once

#include "casteljau/paint/gradient.h"

#include <map>
#include <memory>
#include <pugixml.hpp>
#include <string>
#include <utility>
#include <vector>

namespace casteljau::svg_detail {

inline constexpr int kMaxHrefChain = 64;

struct GradientRef {
    std::shared_ptr<const Gradient> gradient; // null: not a gradient, or unusable
    std::string warning;                      // why, when null
    pugi::xml_node where;                     // the element the warning is about
};

// An invalid value or a broken chain, recovered from: the reader warns (or,
// strict, fails).
struct GradientProblem {
    pugi::xml_node where;
    std::string message;
};

class GradientIndex {
  public:
    // `viewport` sizes resolve percentages of userSpaceOnUse gradients.
    GradientIndex(const pugi::xml_node& root, double viewport_w, double viewport_h);
    GradientRef resolve(const std::string& id);
    // The problems found since the last call (each gradient is built once).
    std::vector<GradientProblem> take_problems() { return std::exchange(problems_, {}); }

  private:
    GradientRef build(pugi::xml_node node);
    GradientStop stop(const pugi::xml_node& s, const std::vector<GradientStop>& before);
    std::map<std::string, pugi::xml_node> by_id_;
    std::map<std::string, GradientRef> cache_;
    std::vector<GradientProblem> problems_;
    double vw_, vh_;
};

} // namespace casteljau::svg_detail
