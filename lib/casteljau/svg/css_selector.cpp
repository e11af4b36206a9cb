// CSS selectors: parsing a rule's prelude into selectors (Selectors 4, 17,
// "grammar"; Selectors 3, 10 for the parts level 3 has).
//
//   list       = complex [ ',' complex ]*
//   complex    = compound [ combinator? compound ]*        whitespace alone: descendant
//   combinator = '>' | '+' | '~'                           (8.1, 8.2, 8.3, 15.1, 15.2)
//   compound   = [ type | '*' ]? [ '#'id | '.'class | attribute | pseudo-class ]*
//                [ pseudo-element pseudo-class* ]?         (no whitespace inside)
//   type       = [ '*|' ]? ident                           (5.1; case-sensitive: SVG is XML)
//   attribute  = '[' ws* '|'? ident ws* [ op ws* ( ident | string ) ws* [ 'i' | 's' ]? ws* ]? ']'
//   op         = '=' | '~=' | '|=' | '^=' | '$=' | '*='    (6.1, 6.2; no space inside op)
//   pseudo-class = ':' ( first-child | last-child | only-child | first-of-type
//                | last-of-type | only-of-type | root | scope | empty | link | any-link
//                | hover | active | focus | focus-visible | focus-within | visited
//                | target | target-within | current | past | future | playing | paused )
//                | ':' ( nth-child | nth-last-child | nth-of-type | nth-last-of-type ) '(' An+B ')'
//                | ':not(' list ')' | ':is(' forgiving-list ')' | ':where(' forgiving-list ')'
//   pseudo-element = '::' ident [ '(' ... ')' ]? | ':' ( before | after | first-line | first-letter
//   ) An+B       = odd | even | integer | [+-]?integer? 'n' [ ws* [+-] ws* digits ]?   (CSS Syntax
//   3, 6)
//
// Pseudo-class and pseudo-element names are ASCII case-insensitive.
// User-action pseudo-classes (:hover, ...) are valid and never true in a
// static image: a selector with one matches nothing (and :not(:hover)
// everything). A selector with a pseudo-element is valid but never matches
// an SVG element: it is dropped without a problem.
//
// Invalid (the whole rule is dropped, Selectors 4, 4.1): anything else,
// including `#1a` (an id must be an identifier), a combinator at either end,
// a type after a subclass, an unknown pseudo-class, an empty :not(). The
// arguments of :is() and :where() are forgiving (Selectors 4, 4.2): an
// invalid one is left out, and :is() with none matches nothing.
//
// Valid but unsupported (the rule is dropped, the problem says so):
// namespace prefixes other than `*|` and `[|a]` (@namespace is skipped, so a
// prefix is undeclared), `:nth-child(An+B of S)`, :has(), :lang(), :dir(),
// :host and column pseudo-classes; more than kCssMaxCompounds compounds in a
// complex selector or more than kCssMaxNesting nested :not/:is/:where, which
// bounds the recursion of parsing (and of matching) whatever the input.
//
// Specificity (16): ids, then classes, attributes and pseudo-classes, then
// types; :not() and :is() count their most specific argument, :where() none.
#include "casteljau/svg/detail/css_selector.h"

#include <algorithm>
#include <optional>
#include <utility>

namespace casteljau::css_detail {

namespace {

struct Invalid {
    std::string why;
    bool unsupported = false;
};

std::string lower(std::string s) {
    for (char& c : s)
        if (c >= 'A' && c <= 'Z') c = char(c | 0x20);
    return s;
}

bool is_one_of(std::string_view name, std::initializer_list<std::string_view> names) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// The pieces of `t` between commas outside any block.
std::vector<std::span<const Token>> split_commas(std::span<const Token> t) {
    std::vector<std::span<const Token>> out;
    std::vector<Tok> open;
    std::size_t start = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i].type == Tok::Comma && open.empty()) {
            out.push_back(t.subspan(start, i - start));
            start = i + 1;
        } else if (const Tok close = closer_of(t[i].type); close != Tok::Eof) {
            open.push_back(close);
        } else if (!open.empty() && t[i].type == open.back()) {
            open.pop_back();
        }
    }
    out.push_back(t.subspan(start));
    return out;
}

// An+B (CSS Syntax 3, 6) from its text, comments already turned to spaces.
std::optional<std::pair<std::int64_t, std::int64_t>> parse_nth(const std::string& s) {
    if (s == "odd") return std::pair<std::int64_t, std::int64_t>{2, 1};
    if (s == "even") return std::pair<std::int64_t, std::int64_t>{2, 0};
    std::size_t i = 0;
    const auto sign = [&] {
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) return s[i++] == '-' ? -1 : 1;
        return 1;
    };
    // Saturated at 1e9: no element has a billion siblings, and the
    // arithmetic of matching cannot overflow.
    const auto integer = [&](std::int64_t& v) {
        const std::size_t start = i;
        for (v = 0; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i)
            v = std::min<std::int64_t>(v * 10 + (s[i] - '0'), 1'000'000'000);
        return i > start;
    };
    const auto spaces = [&] {
        while (i < s.size() && s[i] == ' ') ++i;
    };
    const int a_sign = sign();
    std::int64_t a;
    const bool digits = integer(a);
    if (i < s.size() && s[i] == 'n') {
        a = digits ? a_sign * a : a_sign;
        ++i;
        spaces();
        if (i == s.size()) return std::pair{a, std::int64_t(0)};
        if (s[i] != '+' && s[i] != '-') return std::nullopt;
        const int b_sign = sign();
        spaces();
        std::int64_t b;
        if (!integer(b) || i != s.size()) return std::nullopt;
        return std::pair{a, b_sign * b};
    }
    if (!digits || i != s.size()) return std::nullopt;
    return std::pair{std::int64_t(0), a_sign * a};
}

class Reader {
  public:
    Reader(std::span<const Token> t, std::string_view source, int depth)
        : source_(source), depth_(depth) {
        while (!t.empty() && t.front().type == Tok::Whitespace) t = t.subspan(1);
        while (!t.empty() && t.back().type == Tok::Whitespace) t = t.first(t.size() - 1);
        t_ = t;
    }

    // `never`: it has a pseudo-element.
    Complex complex(bool& never) {
        Complex out;
        if (t_.empty()) fail("an empty selector");
        Combinator left = Combinator::Descendant;
        for (;;) {
            Compound c = compound(out.specificity, never);
            c.left = left;
            out.compounds.push_back(std::move(c));
            if (out.compounds.size() > std::size_t(kCssMaxCompounds))
                fail(cat("more than ", std::to_string(kCssMaxCompounds), " compound selectors"),
                     true);
            if (i_ == t_.size()) return out;
            const bool space = skip_ws();
            const Token& t = t_[i_]; // the trailing whitespace is trimmed
            if (t.is_delim('>') || t.is_delim('+') || t.is_delim('~')) {
                left = t.is_delim('>')   ? Combinator::Child
                       : t.is_delim('+') ? Combinator::Next
                                         : Combinator::Subsequent;
                ++i_;
                skip_ws();
                if (i_ == t_.size()) fail(cat("'", text(t), "' with no selector after it"));
            } else if (space) {
                left = Combinator::Descendant;
            } else {
                fail(cat("unexpected '", text(t), "'"));
            }
            if (never) fail("a pseudo-element must end the selector");
        }
    }

  private:
    [[noreturn]] static void fail(std::string why, bool unsupported = false) {
        throw Invalid{std::move(why), unsupported};
    }
    const Token* peek(std::size_t k = 0) const {
        return i_ + k < t_.size() ? &t_[i_ + k] : nullptr;
    }
    bool skip_ws() {
        const std::size_t from = i_;
        while (i_ < t_.size() && t_[i_].type == Tok::Whitespace) ++i_;
        return i_ > from;
    }
    std::string text(const Token& t) const {
        return std::string(source_.substr(t.begin, t.end - t.begin));
    }
    bool at_delim(std::size_t k, char c) const { return peek(k) && peek(k)->is_delim(c); }

    Compound compound(Specificity& spec, bool& never) {
        Compound out;
        bool any = false;
        const Token* t = peek();
        if (t && (t->type == Tok::Ident || t->is_delim('*') || t->is_delim('|'))) {
            if (t->is_delim('|') || at_delim(1, '|')) { // a namespace prefix
                if (!t->is_delim('*'))
                    fail(cat("namespace prefix in '", text(*t), "|' (@namespace is not supported)"),
                         true);
                i_ += 2;
                t = peek();
                if (!t || !(t->type == Tok::Ident || t->is_delim('*')))
                    fail("expected a type after '*|'");
            }
            if (t->type == Tok::Ident) {
                out.type = t->value;
                spec += kSpecType;
            }
            ++i_;
            any = true;
        }
        for (;; any = true) {
            t = peek();
            if (!t || t->type == Tok::Whitespace || t->is_delim('>') || t->is_delim('+') ||
                t->is_delim('~'))
                break;
            if (never && t->type != Tok::Colon)
                fail("only pseudo-classes may follow a pseudo-element");
            if (t->type == Tok::Hash) {
                if (!t->id) fail(cat("'", text(*t), "' is not an id (not an identifier)"));
                out.simples.push_back({.kind = Simple::Kind::Id, .name = t->value});
                spec += kSpecId;
                ++i_;
            } else if (t->is_delim('.') && peek(1) && peek(1)->type == Tok::Ident) {
                out.simples.push_back({.kind = Simple::Kind::Class, .name = peek(1)->value});
                spec += kSpecClass;
                i_ += 2;
            } else if (t->type == Tok::LBracket) {
                attribute(out);
                spec += kSpecClass;
            } else if (t->type == Tok::Colon) {
                pseudo(out, spec, never);
            } else if (t->type == Tok::Ident || t->is_delim('*')) {
                fail(cat("a type selector must come first ('", text(*t), "')"));
            } else {
                fail(cat("unexpected '", text(*t), "'"));
            }
        }
        if (!any) fail(t ? cat("expected a selector at '", text(*t), "'") : "expected a selector");
        return out;
    }

    void attribute(Compound& out) {
        ++i_;
        skip_ws();
        Simple s{.kind = Simple::Kind::Attr};
        if (at_delim(0, '*') && at_delim(1, '|'))
            fail("attributes in any namespace ([*|a]) are not supported", true);
        if (at_delim(0, '|') && peek(1) && peek(1)->type == Tok::Ident) ++i_; // [|a] is [a]
        const Token* t = peek();
        if (!t || t->type != Tok::Ident) fail("expected an attribute name after '['");
        s.name = t->value;
        ++i_;
        if (at_delim(0, '|') && !at_delim(1, '='))
            fail(cat("namespace prefix in '[", s.name, "|' (@namespace is not supported)"), true);
        skip_ws();
        t = peek();
        if (t && t->type != Tok::RBracket) {
            if (t->is_delim('=')) {
                s.op = AttrOp::Equals;
                ++i_;
            } else {
                const Token* eq = peek(1);
                if (t->type != Tok::Delim || !eq || !eq->is_delim('=') || eq->begin != t->end)
                    fail(cat("expected ']' or an operator in '[", s.name, "'"));
                const char c = t->value[0];
                s.op = c == '~'   ? AttrOp::Includes
                       : c == '|' ? AttrOp::DashMatch
                       : c == '^' ? AttrOp::Prefix
                       : c == '$' ? AttrOp::Suffix
                       : c == '*'
                           ? AttrOp::Substring
                           : (fail(cat("unknown operator '", text(*t), "='")), AttrOp::Exists);
                i_ += 2;
            }
            skip_ws();
            t = peek();
            if (!t || (t->type != Tok::Ident && t->type != Tok::String))
                fail(cat("expected an identifier or a string after the operator in '[", s.name,
                         "'"));
            s.value = t->value;
            ++i_;
            skip_ws();
            t = peek();
            if (t && t->type == Tok::Ident) {
                const std::string flag = lower(t->value);
                if (flag != "i" && flag != "s")
                    fail(cat("unknown attribute flag '", t->value, "'"));
                s.ignore_case = flag == "i";
                ++i_;
                skip_ws();
                t = peek();
            }
        }
        if (!t || t->type != Tok::RBracket) fail(cat("expected ']' in '[", s.name, "'"));
        ++i_;
        out.simples.push_back(std::move(s));
    }

    // The arguments of the function token at i_, and i_ past its ')'.
    std::span<const Token> function_args() {
        const std::size_t from = ++i_;
        for (std::vector<Tok> open{Tok::RParen}; i_ < t_.size(); ++i_) {
            if (const Tok close = closer_of(t_[i_].type); close != Tok::Eof)
                open.push_back(close);
            else if (t_[i_].type == open.back())
                open.pop_back();
            if (open.empty()) return t_.subspan(from, i_++ - from);
        }
        return t_.subspan(from);
    }

    void pseudo(Compound& out, Specificity& spec, bool& never) {
        ++i_;
        const bool element = peek() && peek()->type == Tok::Colon;
        if (element) ++i_;
        const Token* t = peek();
        if (!t || (t->type != Tok::Ident && t->type != Tok::Function))
            fail(cat("expected a name after '", element ? "::" : ":", "'"));
        const std::string name = lower(t->value);
        if (element || (t->type == Tok::Ident &&
                        is_one_of(name, {"before", "after", "first-line", "first-letter"}))) {
            if (depth_ > 0) fail("a pseudo-element inside :not(), :is() or :where()");
            if (never) fail("two pseudo-elements");
            if (t->type == Tok::Function)
                function_args();
            else
                ++i_;
            never = true;
            spec += kSpecType;
            return;
        }
        Simple s;
        using K = Simple::Kind;
        if (t->type == Tok::Ident) {
            ++i_;
            spec += kSpecClass;
            const auto nth = [&](bool from_end) {
                s = {.kind = K::Nth, .from_end = from_end, .of_type = true, .a = 0, .b = 1};
            };
            if (name == "first-child")
                s.kind = K::FirstChild;
            else if (name == "last-child")
                s.kind = K::LastChild;
            else if (name == "only-child")
                s.kind = K::OnlyChild;
            else if (name == "first-of-type")
                nth(false);
            else if (name == "last-of-type")
                nth(true);
            else if (name == "only-of-type") {
                nth(false);
                out.simples.push_back(s);
                nth(true);
            } else if (name == "root" || name == "scope") // no scoping root: :scope is :root
                s.kind = K::Root;
            else if (name == "empty")
                s.kind = K::Empty;
            else if (name == "link" || name == "any-link") // nothing is visited in an image
                s.kind = K::Link;
            else if (is_one_of(name, {"hover", "active", "focus", "focus-visible", "focus-within",
                                      "visited", "target", "target-within", "current", "past",
                                      "future", "playing", "paused"}))
                s.kind = K::Never;
            else if (is_one_of(name, {"host", "defined", "fullscreen", "modal"}))
                fail(cat("':", name, "' is not supported"), true);
            else
                fail(cat("unknown pseudo-class ':", name, "'"));
            out.simples.push_back(std::move(s));
            return;
        }
        const std::span<const Token> args = function_args();
        if (is_one_of(name, {"nth-child", "nth-last-child", "nth-of-type", "nth-last-of-type"})) {
            std::string an_b;
            const Token* previous = nullptr;
            for (const Token& a : args) {
                if (a.type == Tok::Whitespace) continue;
                if (a.type == Tok::Ident && lower(a.value) == "of")
                    fail(cat("':", name, "(... of S)' is not supported"), true);
                if (previous && a.begin != previous->end) an_b += ' ';
                an_b += lower(text(a));
                previous = &a;
            }
            const auto ab = parse_nth(an_b);
            if (!ab) fail(cat("':", name, "(", an_b, ")' is not An+B"));
            s = {.kind = K::Nth,
                 .from_end = name.find("last") != name.npos,
                 .of_type = name.find("type") != name.npos,
                 .a = ab->first,
                 .b = ab->second};
            spec += kSpecClass;
        } else if (name == "not" || name == "is" || name == "where") {
            if (depth_ >= kCssMaxNesting)
                fail(cat("more than ", std::to_string(kCssMaxNesting),
                         " nested :not(), :is() or :where()"),
                     true);
            Specificity most = 0;
            if (name == "not") {
                SelectorList inner = parse_selector_list(args, source_, depth_ + 1);
                if (!inner.error.empty()) fail(cat(":not(): ", inner.error), inner.unsupported);
                s.args = std::move(inner.selectors);
            } else {
                for (const std::span<const Token> piece : split_commas(args)) {
                    try {
                        bool ignored = false;
                        s.args.push_back(Reader(piece, source_, depth_ + 1).complex(ignored));
                    } catch (const Invalid& e) {
                        if (e.unsupported) throw;
                    }
                }
            }
            for (const Complex& c : s.args) most = std::max(most, c.specificity);
            s.kind = name == "not" ? K::Not : K::Is;
            if (name != "where") spec += most;
        } else if (is_one_of(name, {"has", "lang", "dir", "host", "host-context", "nth-col",
                                    "nth-last-col", "state"})) {
            fail(cat("':", name, "()' is not supported"), true);
        } else {
            fail(cat("unknown pseudo-class ':", name, "()'"));
        }
        out.simples.push_back(std::move(s));
    }

    std::span<const Token> t_;
    std::string_view source_;
    std::size_t i_ = 0;
    int depth_;
};

} // namespace

SelectorList parse_selector_list(std::span<const Token> tokens, std::string_view source,
                                 int depth) {
    SelectorList out;
    for (const std::span<const Token> piece : split_commas(tokens)) {
        try {
            bool never = false;
            Complex c = Reader(piece, source, depth).complex(never);
            if (!never) out.selectors.push_back(std::move(c));
        } catch (Invalid& e) {
            out.selectors.clear();
            out.error = std::move(e.why);
            out.unsupported = e.unsupported;
            return out;
        }
    }
    return out;
}

} // namespace casteljau::css_detail
