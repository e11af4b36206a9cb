// Internal to the CSS style sheets (not installed): tokens, parsed
// selectors and the rule index, shared by css_tokenizer.h, css.cpp (rules),
// css_selector.cpp (selector parsing) and css_match.cpp (matching).
#pragma once

#include "casteljau/svg/css.h"

#include <cstdint>
#include <deque>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace casteljau::css_detail {

// Concatenates messages. (GCC 12 mistakes `"literal" + std::string(...)`
// for an overlapping copy, -Wrestrict, so messages are built by appending.)
template <class... Parts>
std::string cat(const Parts&... parts) {
    std::string out;
    (out.append(std::string_view(parts)), ...);
    return out;
}

// The token types of CSS Syntax 3, 4 (no comment token: comments separate
// tokens and vanish; a gap between two tokens' offsets shows where one was).
enum class Tok : std::uint8_t {
    Ident,
    Function,
    AtKeyword,
    Hash,
    String,
    BadString,
    Url,
    BadUrl,
    Delim,
    Number,
    Percentage,
    Dimension,
    Whitespace,
    Cdo,
    Cdc,
    Colon,
    Semicolon,
    Comma,
    LBracket,
    RBracket,
    LParen,
    RParen,
    LBrace,
    RBrace,
    Eof
};

struct Token {
    Tok type = Tok::Eof;
    // Ident, Function, AtKeyword, Hash: the name, escapes resolved; String
    // and Url: the contents, escapes resolved; Delim: the character;
    // Dimension: the unit. Otherwise empty.
    std::string value;
    std::uint32_t begin = 0, end = 0; // source offsets, [begin, end)
    std::uint32_t unit = 0;           // Dimension: where the unit starts
    int line = 1;
    bool id = false;      // Hash: what follows '#' is an identifier (an id selector)
    bool escaped = false; // the source holds an escape: value differs from the text
    bool is_delim(char c) const { return type == Tok::Delim && value.size() == 1 && value[0] == c; }
};

// The closing token of a block-opening token, or Eof when `t` opens none.
Tok closer_of(Tok t);

// Specificity (Selectors 4, 16) packed as ids << 42 | classes << 21 | types:
// every count is below 2^21, since a selector has at most
// kCssMaxPreludeTokens tokens.
using Specificity = std::uint64_t;
inline constexpr Specificity kSpecId = Specificity(1) << 42, kSpecClass = Specificity(1) << 21,
                             kSpecType = 1;

enum class Combinator : std::uint8_t { Descendant, Child, Next, Subsequent };
enum class AttrOp : std::uint8_t { Exists, Equals, Includes, DashMatch, Prefix, Suffix, Substring };

// Declared in this order so that Complex is complete where Simple's member
// initializers name std::vector<Complex> (clang instantiates it there).
struct Simple;

struct Compound {
    std::string type; // empty: any element
    std::vector<Simple> simples;
    Combinator left = Combinator::Descendant; // to the compound on the left, if any
};

struct Complex {
    std::vector<Compound> compounds; // left to right
    Specificity specificity = 0;
};

struct Simple {
    enum class Kind : std::uint8_t {
        Id,
        Class,
        Attr,
        Root,
        Empty,
        FirstChild,
        LastChild,
        OnlyChild,
        Nth,   // :nth-child and its relatives: a n + b, from the end, of the type
        Link,  // :link and :any-link: an <a> with an href
        Never, // user-action pseudo-classes (:hover), never true in a static image
        Not,
        Is // :is() and :where()
    };
    Kind kind = Kind::Never;
    AttrOp op = AttrOp::Exists;
    bool ignore_case = false; // [a=v i]
    bool from_end = false;    // Nth
    bool of_type = false;     // Nth
    std::int64_t a = 0, b = 0;
    std::string name = {};  // Id, Class: the name; Attr: the attribute
    std::string value = {}; // Attr
    std::vector<Complex> args = {};
};

// A parsed selector list: the selectors, or why there are none. Selectors
// with a pseudo-element (::before) are valid but never match an SVG
// element: they are left out.
struct SelectorList {
    std::vector<Complex> selectors;
    std::string error;        // empty when valid
    bool unsupported = false; // valid CSS that this implementation cannot match
};

// Parses a selector list (Selectors 4, 17) from a rule's prelude tokens;
// `source` is the sheet they were read from. `depth` counts the enclosing
// :not() / :is() / :where().
SelectorList parse_selector_list(std::span<const Token> tokens, std::string_view source,
                                 int depth = 0);

struct StringHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
};
using Buckets =
    std::unordered_map<std::string, std::vector<std::uint32_t>, StringHash, std::equal_to<>>;

struct SheetData {
    struct Rule {
        std::uint32_t first = 0, count = 0; // into declarations
    };
    struct Entry {
        Complex selector;
        std::uint32_t rule = 0; // its index is its source order
    };
    // A deque: its elements keep their addresses as later sheets are added.
    std::deque<CssDeclaration> declarations;
    std::vector<Rule> rules;
    std::vector<Entry> entries;
    // Entries by the id, else the first class, else the type of their
    // rightmost compound; the rest in `universal`. Each list in source order.
    Buckets by_id, by_class, by_type;
    std::vector<std::uint32_t> universal;
    std::vector<CssFontFace> font_faces;
    bool full = false; // kCssMaxSelectors reached: later rules are dropped

    // Files `selectors` under rule `rule`.
    void add(std::vector<Complex> selectors, std::uint32_t rule);
};

} // namespace casteljau::css_detail
