// Internal to the SVG reader (not installed): gradient elements -> Gradient.
//
// Every element with an id is indexed once, so gradients may be defined
// anywhere in the document. A reference resolves along the href chain
// (href or xlink:href, SVG 1.1 13.2.2 and 13.2.3): each attribute comes from
// the first gradient of the chain that has it, the stops from the first that
// has any. The chain stops at a missing id, at a link that would close a
// cycle and after kMaxHrefChain links: the gradient uses what it has. Stops
// (13.2.4): offsets are numbers or percentages, clamped to [0, 1] and made
// nondecreasing. stop-color and stop-opacity are properties like any other
// (SVG 2, 13.3.1): their values come from the reader's cascade (presentation
// attributes, style sheets, the style attribute, !important), through
// GradientStyle. Neither is inherited unless declared `inherit`: then the
// parent's value, the gradient element's, itself perhaps declared or
// inherited. stop-color is a color, or currentColor: the stop's computed
// `color` (which is inherited), also when it reaches the stop through
// inherit (CSS Color 4: currentcolor's computed value is the keyword);
// initially black. stop-opacity is a number or a percentage, clamped to
// [0, 1]; initially 1. An invalid declaration is a problem, told about the
// element that declared it, and is dropped, as CSS drops it: the one before
// it in the cascade applies, or the initial value.
#pragma once

#include "casteljau/paint/gradient.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace casteljau::svg_detail {

struct GradientRef {
    std::shared_ptr<const Gradient> gradient; // null: not a gradient, or unusable
    std::string warning;                      // why, when null
    bool paints_none = false;                 // a gradient without stops: none, not the fallback
    pugi::xml_node where;                     // the element the warning is about
};

// An invalid value or a broken chain, recovered from: the reader warns (or,
// strict, fails).
struct GradientProblem {
    pugi::xml_node where;
    std::string message;
};

// What the index needs of the reader's style cascade.
struct GradientStyle {
    // The values declared for a property on an element, in cascade order
    // (the last wins), as declared.
    std::function<std::vector<std::string>(const pugi::xml_node&, const char*)> declarations;
    // The element's computed `color`: what currentColor is there.
    std::function<Rgba(const pugi::xml_node&)> current_color;
};

class GradientIndex {
  public:
    // `viewport` sizes resolve percentages of userSpaceOnUse gradients.
    GradientIndex(const pugi::xml_node& root, double viewport_w, double viewport_h,
                  GradientStyle style);
    GradientRef resolve(const std::string& id);
    // The problems found since the last call (each gradient is built once).
    std::vector<GradientProblem> take_problems() { return std::exchange(problems_, {}); }

  private:
    GradientRef build(pugi::xml_node node);
    GradientStop stop(const pugi::xml_node& s, const std::vector<GradientStop>& before);
    // A stop property's specified value and the element that declared it,
    // `inherit` followed up the tree; nullopt for the initial value.
    struct Specified {
        std::string value; // trimmed
        pugi::xml_node where;
    };
    std::optional<Specified> specified(const pugi::xml_node& s, const char* property,
                                       bool (*valid)(std::string_view), const char* expected,
                                       const char* initial);
    GradientStyle style_;
    std::map<std::string, pugi::xml_node> by_id_;
    std::map<std::string, GradientRef> cache_;
    std::vector<GradientProblem> problems_;
    double vw_, vh_;
};

} // namespace casteljau::svg_detail
