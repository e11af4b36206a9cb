// CSS style sheets: the rule and declaration parser (CSS Syntax 3, 5) over
// the tokenizer of detail/css_tokenizer.h (CSS Syntax 3, 4). Selectors are
// css_selector.cpp's, matching is css_match.cpp's.
//
// Rules (5.4.1 "consume a list of rules", top level): whitespace, <!-- and
// --> are skipped; an at-rule is skipped to its ';' or through its `{}`
// block, nested blocks balanced (5.4.2); anything else starts a qualified
// rule whose prelude runs to the first '{' outside any (), [] or {} block
// (5.4.3), and a prelude that reaches the end of the sheet is dropped.
//
// Blocks (5.4.5 "consume a list of declarations"): ';' and whitespace are
// skipped; `ident ws* ':' value` is a declaration, its value running to the
// next ';' or '}' outside nested blocks; a trailing `! important` (any case,
// any whitespace or comment between) flags it (5.4.6). Anything else is an
// error skipped to the next ';' (or '}' closing the block). As in CSS
// Nesting 1 (and browsers since 2023), a '{' block that a non-declaration
// reaches ends it: `rect { ... }` inside a rule is a nested rule (skipped,
// unsupported) rather than junk running on to the next ';'. An at-rule
// inside a block ends at a '}' closing the block (CSS Syntax 3, 2024 draft).
// A block or string left open at the end of the sheet is closed there.
//
// No recursion: nested blocks are tracked with a stack of closing tokens,
// so any nesting depth costs memory linear in the input and no stack.
#include "casteljau/svg/css.h"

#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/detail/css_selector.h"
#include "casteljau/svg/detail/css_tokenizer.h"
#include "casteljau/svg/media_query.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace casteljau {

namespace css_detail {

Tok closer_of(Tok t) {
    switch (t) {
    case Tok::Function:
    case Tok::LParen:
        return Tok::RParen;
    case Tok::LBracket:
        return Tok::RBracket;
    case Tok::LBrace:
        return Tok::RBrace;
    default:
        return Tok::Eof;
    }
}

namespace {

// Tracks nested blocks: opens on (, [, { and functions, closes on the
// matching token; a closing token that matches nothing open is an
// ordinary token (CSS Syntax 3, 5.4.8 "consume a simple block").
void track(std::vector<Tok>& open, Tok t) {
    if (const Tok close = closer_of(t); close != Tok::Eof)
        open.push_back(close);
    else if (!open.empty() && t == open.back())
        open.pop_back();
}

class Parser {
  public:
    Parser(std::string_view text, std::vector<CssProblem>& problems, MediaContext media = {})
        : text_(text), tokens_(text, problems), problems_(problems), media_(media) {}

    void sheet(css_detail::SheetData& data) { rules(data, false, 0); }

    // Rules to the end, or (`in_block`) to the '}' closing an @media block.
    // False when the selector limit is reached (the rest is then ignored).
    // The sheet's leading @import rules are css_imports'; one after another
    // rule is invalid (CSS Cascade 4, 2.1), and ignored.
    bool rules(css_detail::SheetData& data, bool in_block, int depth) {
        bool leading = !in_block; // nothing but @charset and @import so far
        for (;;) {
            Token t = tokens_.next();
            if (t.type == Tok::Eof) return in_block ? !ended() : true;
            if (t.type == Tok::RBrace && in_block) return true;
            if (t.type == Tok::Whitespace || t.type == Tok::Cdo || t.type == Tok::Cdc) continue;
            const bool at = t.type == Tok::AtKeyword;
            if (at && svg_detail::iequals(t.value, "import")) {
                if (!leading)
                    problem(t.line, "@import after other rules is ignored (CSS Cascade 4, 2.1)");
                skip_at_rule(false);
                continue;
            }
            leading = leading && at && svg_detail::iequals(t.value, "charset");
            if (at && svg_detail::iequals(t.value, "media") && depth < kMaxMediaDepth) {
                if (!media(t, data, depth)) return false;
            } else if (t.type == Tok::AtKeyword && svg_detail::iequals(t.value, "font-face")) {
                font_face(t, data);
            } else if (t.type == Tok::AtKeyword) {
                at_rule(t, false);
            } else if (!rule(std::move(t), data)) {
                return false;
            }
        }
    }

    // Declarations up to the '}' closing their block (`in_block`) or the end.
    // Returns false when the end of the sheet came first.
    bool declarations(std::vector<CssDeclaration>& out, bool in_block, bool report) {
        for (;;) {
            Token t = tokens_.next();
            if (t.type == Tok::Eof) return false;
            if (t.type == Tok::RBrace && in_block) return true;
            if (t.type == Tok::Whitespace || t.type == Tok::Semicolon) continue;
            bool ended;
            if (t.type == Tok::AtKeyword) {
                if (report) at_rule_problem(t, true);
                ended = skip_at_rule(in_block);
            } else if (t.type == Tok::Ident) {
                ended = declaration(std::move(t), out, in_block, report);
            } else {
                const int line = t.line;
                const std::uint32_t begin = t.begin;
                ended = junk(line, begin, std::move(t), in_block, report);
            }
            if (ended) return !tokens_ended_;
        }
    }

  private:
    void problem(int line, std::string message, bool unsupported = false) {
        problems_.push_back({line, std::move(message), unsupported});
    }

    // The source from `begin` to `end`, whitespace runs as one space, cut short.
    std::string excerpt(std::uint32_t begin, std::uint32_t end) const {
        std::string out;
        for (std::uint32_t i = begin; i < end && i < text_.size(); ++i) {
            const bool space = is_space(static_cast<unsigned char>(text_[i]));
            if (space && (out.empty() || out.back() == ' ')) continue;
            if (out.size() == 40) return out.append("...");
            out += space ? ' ' : text_[i];
        }
        while (!out.empty() && out.back() == ' ') out.pop_back();
        return out;
    }

    void at_rule_problem(const Token& t, bool nested) {
        const std::string name = cat("@", t.value);
        if (svg_detail::iequals(t.value, "charset") && !nested)
            return; // meaningless in decoded text
        if (nested)
            problem(t.line, cat(name, " inside a rule is not supported; skipped"), true);
        else
            problem(t.line, cat(name, " is not supported; skipped with its block"), true);
    }

    // An @media rule (svg/media_query.h): its block's rules when its query
    // matches, else skipped. False when the selector limit is reached.
    bool media(const Token& at, css_detail::SheetData& data, int depth) {
        std::vector<Tok> open;
        Token t = tokens_.next();
        for (; t.type != Tok::LBrace || !open.empty(); t = tokens_.next()) {
            if (t.type == Tok::Eof || (t.type == Tok::Semicolon && open.empty())) {
                problem(at.line, "@media without a { block; ignored");
                return true;
            }
            track(open, t.type);
        }
        std::string unknown;
        if (media_matches(text_.substr(at.end, t.begin - at.end), media_, &unknown))
            return rules(data, true, depth + 1);
        if (!unknown.empty())
            problem(at.line,
                    cat("@media ", unknown, " is unknown to a picture: its block is skipped"),
                    true);
        skip_block();
        return true;
    }

    // An @font-face rule: its block's declarations, kept as they are (what
    // they mean is the reader's, svg/font_face.h). A prelude is an error.
    void font_face(const Token& at, css_detail::SheetData& data) {
        Token t = tokens_.next();
        while (t.type == Tok::Whitespace) t = tokens_.next();
        if (t.type != Tok::LBrace) {
            problem(at.line, "@font-face without a { block right after it; ignored");
            if (t.type == Tok::Semicolon) return;
            if (t.type != Tok::Eof) skip_at_rule(false);
            return;
        }
        CssFontFace rule{at.line, {}};
        declarations(rule.descriptors, true, true);
        data.font_faces.push_back(std::move(rule));
    }

    void at_rule(const Token& t, bool nested) {
        at_rule_problem(t, nested);
        skip_at_rule(nested);
    }

    // After an at-keyword: to its ';', through its block, or (nested) to the
    // '}' closing the enclosing block. True when that '}' or the end came.
    bool skip_at_rule(bool nested) {
        std::vector<Tok> open;
        for (;;) {
            const Token t = tokens_.next();
            if (t.type == Tok::Eof) return ended();
            if (open.empty()) {
                if (t.type == Tok::Semicolon) return false;
                if (t.type == Tok::RBrace && nested) return true;
                if (t.type == Tok::LBrace) {
                    skip_block();
                    return false;
                }
            }
            track(open, t.type);
        }
    }

    // After a '{': through its '}'.
    void skip_block() {
        std::vector<Tok> open{Tok::RBrace};
        while (!open.empty()) {
            const Token t = tokens_.next();
            if (t.type == Tok::Eof) {
                ended();
                return;
            }
            track(open, t.type);
        }
    }

    bool ended() {
        tokens_ended_ = true;
        return true;
    }

    // A qualified rule from its first token. False when the selector limit
    // is reached (the rest of the sheet is then ignored).
    bool rule(Token first, css_detail::SheetData& data) {
        const int line = first.line;
        const std::uint32_t begin = first.begin;
        std::vector<Token> prelude;
        std::vector<Tok> open;
        bool too_long = false;
        Token t = std::move(first);
        for (; t.type != Tok::LBrace || !open.empty(); t = tokens_.next()) {
            if (t.type == Tok::Eof) {
                problem(line, cat("'", excerpt(begin, t.begin), "' has no { block; ignored"));
                return true;
            }
            track(open, t.type);
            if (prelude.size() < kCssMaxPreludeTokens)
                prelude.push_back(std::move(t));
            else
                too_long = true;
        }
        css_detail::SelectorList list;
        if (too_long) {
            list.error = cat("more than ", std::to_string(kCssMaxPreludeTokens), " tokens");
            list.unsupported = true;
        } else {
            list = css_detail::parse_selector_list(prelude, text_);
        }
        const bool keep = list.error.empty();
        if (!keep)
            problem(line,
                    cat("selector '", excerpt(begin, t.begin), "': ", list.error, "; rule ignored"),
                    list.unsupported);
        if (keep && data.entries.size() + list.selectors.size() > kCssMaxSelectors) {
            problem(line, cat("more than ", std::to_string(kCssMaxSelectors),
                              " selectors (the limit): this rule and all after it ignored"));
            data.full = true;
            return false;
        }
        std::vector<CssDeclaration> declared;
        if (!declarations(declared, true, keep) && keep)
            problem(line, cat("the block of '", excerpt(begin, t.begin),
                              "' is not closed before the end of the sheet"));
        if (keep && !declared.empty() && !list.selectors.empty()) {
            const css_detail::SheetData::Rule r{std::uint32_t(data.declarations.size()),
                                                std::uint32_t(declared.size())};
            for (CssDeclaration& d : declared) data.declarations.push_back(std::move(d));
            data.rules.push_back(r);
            data.add(std::move(list.selectors), std::uint32_t(data.rules.size() - 1));
        }
        return true;
    }

    // Something that is not a declaration, from `t`: skipped to the next ';',
    // to the '}' closing the block (then true), or through a nested rule's
    // block.
    bool junk(int line, std::uint32_t begin, Token t, bool in_block, bool report) {
        std::vector<Tok> open;
        std::uint32_t end = t.begin;
        bool nested_rule = false, closed = false;
        for (;; t = tokens_.next()) {
            if (t.type == Tok::Eof) {
                closed = ended();
                break;
            }
            if (open.empty()) {
                if (t.type == Tok::Semicolon) break;
                if (t.type == Tok::RBrace && in_block) {
                    closed = true;
                    break;
                }
                if (t.type == Tok::LBrace) {
                    nested_rule = true;
                    skip_block();
                    break;
                }
            }
            track(open, t.type);
            end = t.end;
        }
        if (report) {
            if (nested_rule)
                problem(
                    line,
                    cat("nested rule '", excerpt(begin, end), " {...}' is not supported; skipped"),
                    true);
            else
                problem(line, cat("'", excerpt(begin, end), "' is not a declaration; ignored"));
        }
        return closed;
    }

    // Appends a token's text to a serialized value: the source, or with
    // escapes resolved where they spell a name.
    void append(std::string& value, const Token& t) const {
        const std::string_view source = text_.substr(t.begin, t.end - t.begin);
        if (!t.escaped) return value.append(source), void();
        switch (t.type) {
        case Tok::Ident:
            value += t.value;
            break;
        case Tok::Function:
            value.append(t.value).append("(");
            break;
        case Tok::Hash:
            value.append("#").append(t.value);
            break;
        case Tok::Dimension:
            value.append(text_.substr(t.begin, t.unit - t.begin)).append(t.value);
            break;
        default:
            value.append(source);
        }
    }

    // From the property's name; true when the block (or sheet) ended.
    bool declaration(Token name, std::vector<CssDeclaration>& out, bool in_block, bool report) {
        Token t = tokens_.next();
        while (t.type == Tok::Whitespace) t = tokens_.next();
        if (t.type != Tok::Colon)
            return junk(name.line, name.begin, std::move(t), in_block, report);
        std::string value;
        std::vector<Tok> open;
        bool bad = false, closed = false;
        std::uint32_t previous_end = 0;
        // The last two tokens that are not whitespace: "!" then "important"?
        std::size_t bang_at = std::string::npos, last_bang_at = std::string::npos;
        bool last_important = false;
        for (;;) {
            t = tokens_.next();
            if (t.type == Tok::Eof) {
                closed = ended();
                break;
            }
            if (open.empty()) {
                if (t.type == Tok::Semicolon) break;
                if (t.type == Tok::RBrace && in_block) {
                    closed = true;
                    break;
                }
                if (t.type == Tok::LBrace && !value.empty()) // `a:hover { ... }`: a nested rule
                    return junk(name.line, name.begin, std::move(t), in_block, report);
            }
            track(open, t.type);
            if (t.type == Tok::Whitespace) continue;
            bad = bad || t.type == Tok::BadString || t.type == Tok::BadUrl;
            if (!value.empty() && t.begin != previous_end) value += ' ';
            bang_at = last_bang_at;
            last_bang_at = t.is_delim('!') ? value.size() : std::string::npos;
            last_important = t.type == Tok::Ident && svg_detail::iequals(t.value, "important");
            append(value, t);
            previous_end = t.end;
        }
        CssDeclaration d{name.value, std::move(value), false, name.line};
        if (last_important && bang_at != std::string::npos) {
            d.important = true;
            d.value.resize(bang_at);
            while (!d.value.empty() && d.value.back() == ' ') d.value.pop_back();
        }
        const bool custom = d.name.rfind("--", 0) == 0;
        if (!custom)
            for (char& c : d.name)
                if (c >= 'A' && c <= 'Z') c = char(c | 0x20);
        if (bad) {
            if (report)
                problem(name.line, cat("property ", d.name,
                                       ": an unclosed string or a malformed url(); ignored"));
        } else if (d.value.empty() && !custom) {
            if (report) problem(name.line, cat("property ", d.name, " has no value; ignored"));
        } else {
            out.push_back(std::move(d));
        }
        return closed;
    }

    std::string_view text_;
    Tokenizer tokens_;
    std::vector<CssProblem>& problems_;
    MediaContext media_;
    bool tokens_ended_ = false;
};

} // namespace
} // namespace css_detail

std::vector<CssDeclaration> parse_css_declarations(std::string_view text,
                                                   std::vector<CssProblem>& problems) {
    std::vector<CssDeclaration> out;
    if (text.size() >= std::numeric_limits<std::uint32_t>::max()) {
        problems.push_back({1, "over 4 GiB of CSS; ignored"});
        return out;
    }
    css_detail::Parser(text, problems).declarations(out, false, true);
    return out;
}

// The head of a sheet: @charset, then @import rules, each
//   '@import' ( string | url ) media-query-list? ';'
// (CSS Cascade 4, 2.1; a layer() or supports() condition is not read).
std::vector<CssImport> css_imports(std::string_view css, std::vector<CssProblem>& problems) {
    using css_detail::Tok;
    std::vector<CssImport> out;
    if (css.size() >= std::numeric_limits<std::uint32_t>::max()) return out;
    std::vector<CssProblem> tokens_problems; // StyleSheet::parse reports these
    css_detail::Tokenizer tokens(css, tokens_problems);
    const auto next = [&] {
        css_detail::Token t = tokens.next();
        while (t.type == Tok::Whitespace) t = tokens.next();
        return t;
    };
    // To the ';' ending the rule; its offset, or the end's.
    const auto rule_end = [&](css_detail::Token t) {
        while (t.type != Tok::Semicolon && t.type != Tok::Eof && t.type != Tok::LBrace)
            t = tokens.next();
        return t.type == Tok::Semicolon ? t.begin : std::uint32_t(css.size());
    };
    for (css_detail::Token t = next(); t.type != Tok::Eof; t = next()) {
        if (t.type == Tok::Cdo || t.type == Tok::Cdc) continue;
        if (t.type != Tok::AtKeyword) break;
        if (svg_detail::iequals(t.value, "charset")) {
            rule_end(next());
            continue;
        }
        if (!svg_detail::iequals(t.value, "import")) break;
        CssImport imp{{}, {}, t.line};
        css_detail::Token u = next();
        bool ok = u.type == Tok::String || u.type == Tok::Url;
        if (u.type == Tok::Function && svg_detail::iequals(u.value, "url")) {
            imp.url = next().value; // url("...") is a function holding a string
            u = next();
            ok = u.type == Tok::RParen;
        } else {
            imp.url = u.value;
        }
        const std::uint32_t media_begin = u.end; // past the URL
        const std::uint32_t end = rule_end(ok ? tokens.next() : std::move(u));
        if (!ok) {
            problems.push_back({imp.line, "@import without a URL; skipped"});
            continue;
        }
        imp.media =
            svg_detail::trim(css.substr(media_begin, std::max(end, media_begin) - media_begin));
        if (imp.media.starts_with("layer") || imp.media.starts_with("supports(")) {
            problems.push_back(
                {imp.line, "@import with a layer or supports() condition is not supported; skipped",
                 true});
            continue;
        }
        out.push_back(std::move(imp));
    }
    return out;
}

StyleSheet::StyleSheet() : data_(std::make_unique<css_detail::SheetData>()) {}
StyleSheet::~StyleSheet() = default;
StyleSheet::StyleSheet(StyleSheet&&) noexcept = default;
StyleSheet& StyleSheet::operator=(StyleSheet&&) noexcept = default;

void StyleSheet::parse(std::string_view css, std::vector<CssProblem>& problems,
                       const MediaContext& media) {
    if (data_->full) {
        problems.push_back({1, "the selector limit was reached before this sheet; ignored"});
    } else if (css.size() >= std::numeric_limits<std::uint32_t>::max()) {
        problems.push_back({1, "over 4 GiB of CSS; ignored"});
    } else {
        css_detail::Parser(css, problems, media).sheet(*data_);
    }
}

bool StyleSheet::empty() const { return data_->entries.empty(); }
std::size_t StyleSheet::size() const { return data_->entries.size(); }
const std::vector<CssFontFace>& StyleSheet::font_faces() const { return data_->font_faces; }

} // namespace casteljau
