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
// scripting (none); and, when MediaContext gives the size the picture is
// drawn at (the viewport of an SVG image, in px), width, height,
// aspect-ratio (and their device- forms, the same here) and orientation,
// with min-/max- prefixes or in the range syntax of 4.1 (`(width >= 32px)`,
// `(16px < width <= 64px)`). Lengths take px, em and rem (16 px: no font
// size applies), in, cm, mm, Q, pt and pc. Any other feature (resolution,
// hover, ...), or a size feature without a size, is unknown: an unknown
// feature makes its whole query false, as Media Queries 4, 3.2 says of
// unknown values, and is reported so that the caller can warn about it.
#pragma once

#include <string>
#include <string_view>

namespace casteljau {

/// What the picture is rendered for.
struct MediaContext {
    bool dark = false; ///< prefers-color-scheme: dark
    double width = 0;  ///< the viewport's width, px; 0: unknown
    double height = 0; ///< the viewport's height, px; 0: unknown
};

/// Whether the query list `query` (an @media rule's prelude) matches. A
/// feature without an answer here makes its query false and is named in
/// `unknown` (when given), which is left empty otherwise.
bool media_matches(std::string_view query, const MediaContext& media, std::string* unknown);

} // namespace casteljau
