// Conditional processing (SVG 1.1, 5.8; SVG 2, 5.7 and 5.8): whether an
// element's systemLanguage, requiredExtensions and requiredFeatures let it be
// rendered. An element whose conditions fail is not rendered anywhere, and a
// <switch> renders only its first direct child whose conditions hold.
//
// systemLanguage is a comma-separated list of language tags; it holds when
// one of the user's languages equals one of them, or is a prefix of one up
// to a '-' ("en" matches "en-US", SVG 1.1's rule), or one of them is a
// prefix of the user's ("en" in the file matches a user's "en-GB", as
// browsers match). An empty list never holds. requiredExtensions names
// extensions by URI: this renderer has none, so the attribute, even empty,
// fails. requiredFeatures is gone from SVG 2 and browsers treat it as
// holding: so does this reader.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace casteljau {

/// The conditional attributes of one element, when present.
struct Conditions {
    std::optional<std::string_view> system_language;
    std::optional<std::string_view> required_extensions;
};

/// Whether an element with these conditions is rendered for a user whose
/// languages are `languages` (tags such as "en" or "de-CH", in any case).
bool conditions_hold(const Conditions& c, std::span<const std::string> languages);

} // namespace casteljau
