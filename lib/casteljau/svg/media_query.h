// @media conditions (Media Queries 4) as a static image answers them: the
// block of a matching @media rule is read as if it stood outside it, the
// block of any other is skipped.
//
//   query-list = query ( ',' query )*             true when any is (an empty list is)
//   query      = [ 'not' | 'only' ]? type [ 'and' condition ]?  |  condition
//   condition  = 'not' in-parens | in-parens ( ( 'and' | 'or' ) in-parens )*
//   in-parens  = '(' condition ')' | '(' feature [ ':' value ]? ')'
//
// Types: all and screen match; print, speech and any other do not. The
// features a picture has an answer for: prefers-color-scheme (light unless
// MediaContext says dark), prefers-reduced-motion, prefers-contrast,
// prefers-reduced-transparency, forced-colors, inverted-colors (the
// no-preference or none value), color (yes), monochrome (no: 0), grid (no),
// scripting (none). Any other (width, height, aspect-ratio, resolution,
// orientation, hover, ...) is unknown: the style sheets are read before the
// document's size is, and a renderer has no pointer. An unknown feature
// makes its whole query false, as Media Queries 4, 3.2 says of unknown
// values, and is reported so that the caller can warn about it.
#pragma once

#include <string>
#include <string_view>

namespace casteljau {

/// What the picture is rendered for.
struct MediaContext {
    bool dark = false; ///< prefers-color-scheme: dark
};

/// Whether the query list `query` (an @media rule's prelude) matches. A
/// feature without an answer here makes its query false and is named in
/// `unknown` (when given), which is left empty otherwise.
bool media_matches(std::string_view query, const MediaContext& media, std::string* unknown);

} // namespace casteljau
