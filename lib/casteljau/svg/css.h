// CSS style sheets for SVG's <style> elements: parsing, selectors and the
// cascade order of the declarations that match an element.
//
// Accepted grammar (the tokenizer and rules are css.cpp's, the selectors
// css_selector.cpp's, matching css_match.cpp's; each states its part in
// detail):
//
//   sheet        = ( rule | at-rule | CDO | CDC | whitespace )*      CSS Syntax 3, 5.4.1
//   rule         = prelude '{' declarations '}'                      CSS Syntax 3, 5.4.3
//   prelude      = selector-list                                     Selectors 4, 4.1 and 17
//   declarations = ( declaration | ';' | whitespace )*               CSS Syntax 3, 5.4.5
//   declaration  = ident ':' value [ '!' 'important' ]               CSS Syntax 3, 5.4.6
//
// with comments, strings, escapes and blocks as CSS Syntax 3, 4 tokenizes
// them. @media rules are read as a picture answers their query
// (svg/media_query.h): a matching one's block as though it stood alone, the
// others skipped; @font-face rules are kept for the reader. The @import
// rules at a sheet's head are listed by css_imports for the reader to read
// (no file or URL is fetched here); other at-rules are skipped whole, their
// `{}` block balanced (5.4.2).
//
// Errors are recovered from as CSS says: a rule whose selector list holds an
// invalid selector is dropped whole (Selectors 4, 4.1: "an invalid selector
// ... the entire selector list is invalid"); an invalid declaration is
// dropped alone, the parser resuming after the next ';' at its nesting
// level (CSS Syntax 3, 5.4.5); an unclosed block or string ends at the end of
// the sheet, as though closed. Each problem is reported with its line within
// the sheet text; valid CSS this implementation does not apply (an @media
// block, :has()) is reported too, flagged `unsupported`, so that a caller can
// warn about it without treating it as an error in the file.
//
// Why a small element-tree interface (CssTree) rather than pugixml nodes:
// the parser and the cascade do not depend on the XML library, so this
// header stays installable and pugixml stays private to the library (see
// lib/CMakeLists.txt). The reader's pugixml adapter is
// svg/detail/css_pugi.h; the virtual calls cost a few nanoseconds against
// the string comparisons that selector matching does anyway.
//
// Matching is indexed as browsers do it: each selector is filed under the
// id, else one class, else the type of its rightmost compound selector, else
// under "universal", and an element tests only the selectors filed under its
// own id, classes and type, and the universal ones. A test costs at most
// O(depth x compounds) compound tests for descendant and child combinators
// (a failed descendant search ends the whole match, as in WebKit and Servo);
// sibling positions (:nth-child, :last-of-type, ...) and `~` searches are
// cached per parent, so they cost O(1) amortised. A work limit bounds the
// pathological cases (many universal selectors on a huge document).
#pragma once

#include "casteljau/svg/media_query.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

namespace css_detail {
struct SheetData; // the rules and their index: svg/detail/css_selector.h
} // namespace css_detail

/// Selectors (complex selectors: a list `a, b` counts two) kept across all
/// the sheets of a StyleSheet. A rule that would exceed it is dropped, and
/// so is the rest of that sheet and every later one, with one problem.
inline constexpr std::size_t kCssMaxSelectors = 100'000;
/// Compound selectors in one complex selector (`g > .a rect` has three):
/// bounds the recursion depth of matching. A longer selector is invalid for
/// this implementation: its rule is dropped, with an unsupported problem.
inline constexpr int kCssMaxCompounds = 32;
/// Nesting of :not(), :is() and :where() inside each other; deeper is
/// dropped like an overlong selector.
inline constexpr int kCssMaxNesting = 4;
/// Tokens in one rule's selector list; a longer list drops its rule.
inline constexpr std::size_t kCssMaxPreludeTokens = 65'536;
/// @media rules nested deeper than this are skipped with their blocks: the
/// parser reads a matching one's block by recursion.
inline constexpr int kMaxMediaDepth = 16;
/// The default work limit of a CssMatcher, in compound-selector tests:
/// some 4 s on one core at the 40 ns a test costs in the worst case measured
/// (2000 `.cN *` rules), and 100 tests for each of a million elements, where
/// documents with typical sheets need under 20.
inline constexpr std::uint64_t kCssDefaultMaxWork = 100'000'000;

/// One declaration of a style sheet rule (or of a style attribute).
struct CssDeclaration {
    /// The property, ASCII-lowercased (CSS property names are case-insensitive),
    /// except custom properties (`--x`), which keep their case.
    std::string name;
    /// The value as text, trimmed, without `!important`: whitespace and
    /// comments between tokens become one space; escapes in identifiers are
    /// resolved, strings and url() keep their source text.
    std::string value;
    bool important = false; ///< the declaration ended with `!important`
    int line = 0;           ///< 1-based line of its name within the sheet text
};

/// Something in a sheet that was dropped or skipped.
struct CssProblem {
    int line = 0;        ///< 1-based line within the sheet text
    std::string message; ///< what, and what was done ("...; rule ignored")
    /// Valid CSS that this implementation skips (an at-rule, :has()): worth a
    /// warning, but not an error in the file, even when reading strictly.
    bool unsupported = false;
};

/// An \@font-face rule (CSS Fonts 4, 4.1): its descriptors, read as declarations.
struct CssFontFace {
    int line = 0; ///< 1-based line of the at-keyword within its sheet text
    std::vector<CssDeclaration> descriptors;
};

/// Parses the declarations of a style attribute (CSS Style Attributes, 3:
/// a declaration list without braces), with the same tokenizer and error
/// recovery as a sheet's blocks. Problems are appended to `problems`.
std::vector<CssDeclaration> parse_css_declarations(std::string_view text,
                                                   std::vector<CssProblem>& problems);

/// The elements of a document as selectors see them. An adapter over the
/// caller's tree (the SVG reader's is over pugixml); Node is any pointer
/// that identifies an element, and must stay valid while a CssMatcher uses it.
class CssTree {
  public:
    /// An element, opaque to the style sheet; nullptr is "no element".
    using Node = const void*;
    virtual ~CssTree() = default;
    /// The element's name, compared case-sensitively (SVG is XML).
    virtual std::string_view name(Node element) const = 0;
    /// The value of attribute `name`, or nullptr when the element has none.
    virtual const char* attribute(Node element, const char* name) const = 0;
    /// The parent element; nullptr for the root element.
    virtual Node parent(Node element) const = 0;
    /// The first child that is an element, or nullptr.
    virtual Node first_child(Node element) const = 0;
    /// The previous sibling that is an element, or nullptr.
    virtual Node previous_sibling(Node element) const = 0;
    /// The next sibling that is an element, or nullptr.
    virtual Node next_sibling(Node element) const = 0;
    /// No element children and no text (:empty, Selectors 4, 14.2).
    virtual bool empty(Node element) const = 0;
};

/// An \@import rule at the head of a sheet (CSS Cascade 4, 2.1).
struct CssImport {
    std::string url;   ///< the sheet's URL as written, escapes resolved
    std::string media; ///< the media query list it applies to; "" for all
    int line = 0;      ///< 1-based line of the at-keyword within the sheet text
};

/// The \@import rules at the head of `css` (after any \@charset, before
/// every other rule), in order: the sheets whose rules come before this
/// one's. No file is read here (the SVG reader reads them, within its
/// limits). A malformed one is a problem, and skipped; StyleSheet::parse
/// skips these, and reports an \@import further down (CSS ignores it).
std::vector<CssImport> css_imports(std::string_view css, std::vector<CssProblem>& problems);

/// The rules of a document's style sheets, indexed for matching.
class StyleSheet {
  public:
    /// An empty sheet.
    StyleSheet();
    /// Frees the rules; declarations handed out by a CssMatcher die with it.
    ~StyleSheet();
    /// Movable, not copyable (declarations are handed out by address).
    StyleSheet(StyleSheet&&) noexcept;
    /// Movable, not copyable.
    StyleSheet& operator=(StyleSheet&&) noexcept;

    /// Appends the rules of one `<style>` element's text. With several
    /// `<style>` elements, call it once each, in document order: later rules win ties.
    /// Problems are appended to `problems`, their lines within `css`.
    /// Earlier declarations stay at their addresses.
    /// `media` answers \@media queries (svg/media_query.h).
    void parse(std::string_view css, std::vector<CssProblem>& problems,
               const MediaContext& media = {});

    /// True when no selector was kept (no rule can match anything).
    bool empty() const;
    /// The number of complex selectors kept (`a, b {}` keeps two).
    std::size_t size() const;
    /// The \@font-face rules of the sheets parsed so far, in source order
    /// (those inside a matching \@media block included).
    const std::vector<CssFontFace>& font_faces() const;

  private:
    friend class CssMatcher;
    std::unique_ptr<css_detail::SheetData> data_;
};

/// Finds the declarations that apply to elements of one document.
///
/// The cascade (CSS Cascade 4, 6.1; SVG 2, 6.9 "presentation attributes"):
/// the caller applies, each later step overriding the earlier ones,
///   1. the element's presentation attributes (fill="red"),
///   2. the declarations from match() with important == false, in order,
///   3. the style attribute's declarations with important == false,
///   4. the declarations from match() with important == true, in order,
///   5. the style attribute's declarations with important == true.
/// Within 2 and 4, match() gives ascending (specificity, source order):
/// the last applied wins.
///
/// It caches sibling positions and `~` searches per parent, so make one per
/// document, and throw it away (or make a new one) if the tree changes. One
/// thread at a time; several matchers may share a sheet across threads.
class CssMatcher {
  public:
    /// Matches `sheet` against elements of `tree`; both must outlive it.
    /// `max_work` bounds the compound-selector tests over all match() calls.
    CssMatcher(const StyleSheet& sheet, const CssTree& tree,
               std::uint64_t max_work = kCssDefaultMaxWork);
    /// Frees the caches.
    ~CssMatcher();
    /// Not copyable (it refers to its sheet and tree).
    CssMatcher(const CssMatcher&) = delete;
    /// Not copyable.
    CssMatcher& operator=(const CssMatcher&) = delete;

    /// Replaces `out` with the declarations of every rule matching `element`,
    /// in cascade order: ascending specificity, then source order (rule by
    /// rule, sheet by sheet); a rule's own declarations in their order. A
    /// rule that matches through several selectors of its list appears once,
    /// at its highest specificity. The pointers live as long as the sheet.
    /// Returns false, with `out` incomplete, once the work limit is reached
    /// (and for every later call): the caller should stop, as for any limit.
    bool match(CssTree::Node element, std::vector<const CssDeclaration*>& out);

    /// Compound-selector tests (and sibling steps) done so far.
    std::uint64_t work() const;

  private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace casteljau
