// CSS custom properties and var() (CSS Custom Properties for Cascading
// Variables 1): `--name: value` declarations in style sheets and style
// attributes are inherited like any inherited property, and var(--name) or
// var(--name, fallback) in a CSS declaration's value is replaced by the
// element's value of --name, or the fallback, before the declaration is
// parsed (3, "substitute a var()"). Values are kept as written (trimmed);
// a var() inside one is replaced where it is used, so --a: var(--b) follows
// the element's --b.
//
// A var() naming no custom property and without a fallback makes the
// declaration invalid at computed-value time (3.1): the caller ignores it,
// with a warning (the spec would take the property's inherited or initial
// value rather than an earlier declaration's). Cycles (--a: var(--a)) and
// results beyond a size limit (--a: var(--b) var(--b), --b: ... doubling at
// each level) are invalid the same way: substitution stops at kMaxVarDepth
// nested references and at the caller's size limit, so its work is bounded.
// Presentation attributes take no var() (they are not CSS declarations).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace casteljau {

/// An element's custom properties, name (with its "--") and value; the
/// last of a name wins.
using CustomProperties = std::vector<std::pair<std::string, std::string>>;

/// References followed within one substitution at most (top of the file).
inline constexpr int kMaxVarDepth = 32;

/// Whether `value` holds a var() (ASCII case aside).
bool has_var(std::string_view value);

/// `value` with every var() substituted from `custom` (may be null: none
/// declared), or nullopt when one cannot be (top of the file) or the result
/// would exceed `limit` bytes.
std::optional<std::string> substitute_vars(std::string_view value, const CustomProperties* custom,
                                           std::size_t limit);

} // namespace casteljau
