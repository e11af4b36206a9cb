// CSS math functions on lengths (CSS Values 4, 10): calc(), min(), max()
// and clamp(), with +, -, *, / and parentheses, as a length value.
//
//   sum     = product ( ( ' + ' | ' - ' ) product )*   (whitespace around + and -)
//   product = value ( ( '*' | '/' ) value )*
//   value   = number | dimension | percentage | '(' sum ')'
//           | calc( sum ) | min( sum# ) | max( sum# ) | clamp( sum , sum , sum )
//
// Each leaf is resolved to user units at once (lengths through `leaf`, which
// knows the units and what a percentage is of), so the types that matter
// are two: a number and a length. + and - take two of one type; * takes at
// least one number; / takes a number to the right, not zero. A result that is
// a number stands for user units, as a plain number does in an SVG length.
// Nesting is bounded (kMaxCssMathDepth) and anything else is invalid: nullopt.
#pragma once

#include <functional>
#include <optional>
#include <string_view>

namespace casteljau {

/// Parentheses and functions nested deeper than this make the value invalid.
inline constexpr int kMaxCssMathDepth = 32;

/// Whether `text` starts a math function (calc, min, max or clamp, any case).
bool is_css_math(std::string_view text);

/// The value of the math function `text` in user units; `leaf` resolves one
/// dimension or percentage (nullopt: invalid).
std::optional<double>
eval_css_math(std::string_view text,
              const std::function<std::optional<double>(std::string_view)>& leaf);

} // namespace casteljau
