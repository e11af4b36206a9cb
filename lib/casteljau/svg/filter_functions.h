// The filter property's value (Filter Effects 1, 11 and 12): none, or a
// list of url(#id) references and CSS filter functions.
#pragma once

#include "casteljau/paint/color.h"
#include "casteljau/svg/style.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

/// One item of a filter list.
struct FilterItem {
    /// A url() or one of the functions.
    enum class Kind {
        Url,
        Blur,
        DropShadow,
        Brightness,
        Contrast,
        Grayscale,
        HueRotate,
        Invert,
        Opacity,
        Saturate,
        Sepia
    };
    Kind kind = Kind::Url;
    std::string id;        ///< Url: the id after '#'
    double amount = 0;     ///< the number (a percentage / 100), degrees for hue-rotate, px for blur
    double dx = 0, dy = 0; ///< drop-shadow's offset, px
    std::optional<Rgba> color; ///< drop-shadow's color; currentColor when not given
};

/// The items of a filter value; an empty list for none; nullopt when the
/// value is invalid (a function with a bad or negative argument, an
/// unknown function, a url that is not a local #id).
std::optional<std::vector<FilterItem>> parse_filter_list(std::string_view value,
                                                         const LengthContext& ctx);

} // namespace casteljau
