// CSS style sheets: the tokenizer (CSS Syntax 3, 4) and the rule and
// declaration parser (CSS Syntax 3, 5). Selectors are css_selector.cpp's,
// matching is css_match.cpp's.
//
// Tokens: as 4.3 defines them, with two simplifications that change no
// valid sheet: the input is taken as UTF-8 bytes (a non-ASCII byte is a name
// character, as every non-ASCII code point is, 4.2), and a NUL byte is kept
// rather than replaced by U+FFFD. Comments produce no token (4.3.2); the gap
// they leave between two tokens' offsets is kept when a value is serialized.
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

#include "casteljau/svg/detail/css_selector.h"
#include "casteljau/svg/media_query.h"
#include "casteljau/text/utf8.h"

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

bool is_digit(int c) { return c >= '0' && c <= '9'; }
bool is_hex(int c) { return is_digit(c) || ((c | 0x20) >= 'a' && (c | 0x20) <= 'f'); }
bool is_newline(int c) { return c == '\n' || c == '\r' || c == '\f'; }
bool is_space(int c) { return c == ' ' || c == '\t' || is_newline(c); }
bool is_name_start(int c) {
    return ((c | 0x20) >= 'a' && (c | 0x20) <= 'z') || c == '_' || c >= 0x80;
}
bool is_name(int c) { return is_name_start(c) || is_digit(c) || c == '-'; }
bool is_non_printable(int c) {
    return (c >= 0 && c <= 8) || c == 0x0b || (c >= 0x0e && c <= 0x1f) || c == 0x7f;
}

bool ascii_iequals(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return (x >= 'A' && x <= 'Z' ? x | 0x20 : x) ==
                      (y >= 'A' && y <= 'Z' ? y | 0x20 : y);
           });
}

class Tokenizer {
  public:
    Tokenizer(std::string_view s, std::vector<CssProblem>& problems) : s_(s), problems_(problems) {}

    Token next() {
        while (cur() == '/' && at(pos_ + 1) == '*') {
            const std::size_t close = s_.find("*/", pos_ + 2);
            if (close == s_.npos) {
                problems_.push_back(
                    {line_at(pos_), "a comment is not closed: the rest is ignored"});
                pos_ = s_.size();
            } else {
                pos_ = close + 2;
            }
        }
        Token t;
        t.begin = std::uint32_t(pos_);
        t.line = line_at(pos_);
        const int c = cur();
        if (c < 0) {
            t.end = t.begin;
            return t;
        }
        if (is_space(c)) {
            while (is_space(cur())) ++pos_;
            t.type = Tok::Whitespace;
        } else if (c == '"' || c == '\'') {
            ++pos_;
            string(t, c);
        } else if (c == '#' && (is_name(at(pos_ + 1)) || valid_escape(pos_ + 1))) {
            ++pos_;
            t.type = Tok::Hash;
            t.id = starts_ident(pos_);
            t.value = name(t.escaped);
        } else if ((c == '+' || c == '-' || c == '.') && starts_number(pos_)) {
            numeric(t);
        } else if (c == '-' && at(pos_ + 1) == '-' && at(pos_ + 2) == '>') {
            pos_ += 3;
            t.type = Tok::Cdc;
        } else if (c == '<' && s_.substr(pos_, 4) == "<!--") {
            pos_ += 4;
            t.type = Tok::Cdo;
        } else if (c == '@' && starts_ident(pos_ + 1)) {
            ++pos_;
            t.type = Tok::AtKeyword;
            t.value = name(t.escaped);
        } else if (is_digit(c)) {
            numeric(t);
        } else if (starts_ident(pos_)) {
            ident_like(t);
        } else {
            ++pos_;
            t.type = single(c);
            if (t.type == Tok::Delim) t.value = char(c);
        }
        t.end = std::uint32_t(pos_);
        return t;
    }

  private:
    int at(std::size_t i) const { return i < s_.size() ? static_cast<unsigned char>(s_[i]) : -1; }
    int cur() const { return at(pos_); }
    bool valid_escape(std::size_t i) const { return at(i) == '\\' && !is_newline(at(i + 1)); }
    bool starts_ident(std::size_t i) const {
        const int c = at(i);
        if (c == '-') return is_name_start(at(i + 1)) || at(i + 1) == '-' || valid_escape(i + 1);
        return is_name_start(c) || valid_escape(i);
    }
    bool starts_number(std::size_t i) const {
        int c = at(i);
        if (c == '+' || c == '-') c = at(++i);
        return is_digit(c) || (c == '.' && is_digit(at(i + 1)));
    }

    // Lines are counted lazily, up to each token's start: CR LF, CR, LF and
    // FF each end one (the preprocessing of 3.3).
    int line_at(std::size_t pos) {
        for (; line_pos_ < pos; ++line_pos_) {
            const char c = s_[line_pos_];
            if (c == '\n' || c == '\f' || (c == '\r' && at(line_pos_ + 1) != '\n')) ++line_;
        }
        return line_;
    }

    static Tok single(int c) {
        switch (c) {
        case '(':
            return Tok::LParen;
        case ')':
            return Tok::RParen;
        case '[':
            return Tok::LBracket;
        case ']':
            return Tok::RBracket;
        case '{':
            return Tok::LBrace;
        case '}':
            return Tok::RBrace;
        case ',':
            return Tok::Comma;
        case ':':
            return Tok::Colon;
        case ';':
            return Tok::Semicolon;
        default:
            return Tok::Delim;
        }
    }

    // 4.3.7, after the backslash.
    void escape(std::string& out) {
        const int c = cur();
        if (c < 0) {
            append_utf8(out, 0xfffd);
            return;
        }
        if (is_hex(c)) {
            std::uint32_t cp = 0;
            for (int n = 0; n < 6 && is_hex(cur()); ++n, ++pos_) {
                const int h = cur();
                cp = cp * 16 + std::uint32_t(is_digit(h) ? h - '0' : (h | 0x20) - 'a' + 10);
            }
            if (cur() == '\r' && at(pos_ + 1) == '\n')
                pos_ += 2;
            else if (is_space(cur()))
                ++pos_;
            if (cp == 0 || (cp >= 0xd800 && cp <= 0xdfff) || cp > 0x10ffff) cp = 0xfffd;
            append_utf8(out, cp);
            return;
        }
        out += s_[pos_++]; // the character itself, with the rest of its UTF-8 sequence
        while ((at(pos_) & 0xc0) == 0x80) out += s_[pos_++];
    }

    std::string name(bool& escaped) {
        std::string out;
        for (;;) {
            if (is_name(cur())) {
                out += s_[pos_++];
            } else if (valid_escape(pos_)) {
                ++pos_;
                escape(out);
                escaped = true;
            } else {
                return out;
            }
        }
    }

    void string(Token& t, int quote) {
        t.type = Tok::String;
        for (;;) {
            const int c = cur();
            if (c < 0 || c == quote) {
                if (c == quote) ++pos_;
                return;
            }
            if (is_newline(c)) { // not consumed: the next token starts there
                t.type = Tok::BadString;
                return;
            }
            if (c == '\\') {
                const int d = at(pos_ + 1);
                if (d < 0) {
                    ++pos_;
                } else if (is_newline(d)) { // an escaped newline continues the string
                    pos_ += d == '\r' && at(pos_ + 2) == '\n' ? 3 : 2;
                } else {
                    ++pos_;
                    escape(t.value);
                    t.escaped = true;
                }
                continue;
            }
            t.value += char(c);
            ++pos_;
        }
    }

    void numeric(Token& t) {
        if (cur() == '+' || cur() == '-') ++pos_;
        while (is_digit(cur())) ++pos_;
        if (cur() == '.' && is_digit(at(pos_ + 1)))
            for (++pos_; is_digit(cur());) ++pos_;
        if ((cur() | 0x20) == 'e') {
            const int d = at(pos_ + 1);
            if (is_digit(d) || ((d == '+' || d == '-') && is_digit(at(pos_ + 2))))
                for (pos_ += 2; is_digit(cur());) ++pos_;
        }
        if (starts_ident(pos_)) {
            t.type = Tok::Dimension;
            t.unit = std::uint32_t(pos_);
            t.value = name(t.escaped);
        } else if (cur() == '%') {
            ++pos_;
            t.type = Tok::Percentage;
        } else {
            t.type = Tok::Number;
        }
    }

    void ident_like(Token& t) {
        t.value = name(t.escaped);
        t.type = Tok::Ident;
        if (cur() != '(') return;
        ++pos_;
        t.type = Tok::Function;
        if (!ascii_iequals(t.value, "url")) return;
        std::size_t p = pos_;
        while (is_space(at(p))) ++p;
        if (at(p) != '"' && at(p) != '\'') { // url("...") is a function; url(...) a token
            pos_ = p;
            url(t);
        }
    }

    // 4.3.6, after "url(" and whitespace.
    void url(Token& t) {
        t.type = Tok::Url;
        t.value.clear();
        for (;;) {
            const int c = cur();
            if (c < 0) return;
            if (c == ')') {
                ++pos_;
                return;
            }
            if (is_space(c)) {
                while (is_space(cur())) ++pos_;
                if (cur() < 0 || cur() == ')') continue;
            } else if (c == '\\' && valid_escape(pos_)) {
                ++pos_;
                escape(t.value);
                t.escaped = true;
                continue;
            } else if (c != '"' && c != '\'' && c != '(' && c != '\\' && !is_non_printable(c)) {
                t.value += char(c);
                ++pos_;
                continue;
            }
            // A bad url: skip to ')' (escapes included) or the end.
            t.type = Tok::BadUrl;
            for (int d = cur(); d >= 0 && d != ')'; d = cur()) {
                std::string ignored;
                if (valid_escape(pos_)) {
                    ++pos_;
                    escape(ignored);
                } else {
                    ++pos_;
                }
            }
            if (cur() == ')') ++pos_;
            return;
        }
    }

    std::string_view s_;
    std::vector<CssProblem>& problems_;
    std::size_t pos_ = 0, line_pos_ = 0;
    int line_ = 1;
};

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
    bool rules(css_detail::SheetData& data, bool in_block, int depth) {
        for (;;) {
            Token t = tokens_.next();
            if (t.type == Tok::Eof) return in_block ? !ended() : true;
            if (t.type == Tok::RBrace && in_block) return true;
            if (t.type == Tok::Whitespace || t.type == Tok::Cdo || t.type == Tok::Cdc) continue;
            if (t.type == Tok::AtKeyword && ascii_iequals(t.value, "media") &&
                depth < kMaxMediaDepth) {
                if (!media(t, data, depth)) return false;
            } else if (t.type == Tok::AtKeyword && ascii_iequals(t.value, "font-face")) {
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
        if (ascii_iequals(t.value, "charset") && !nested) return; // meaningless in decoded text
        if (nested)
            problem(t.line, cat(name, " inside a rule is not supported; skipped"), true);
        else if (ascii_iequals(t.value, "import"))
            problem(t.line, "@import is not supported (no style sheet is fetched); skipped", true);
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
            last_important = t.type == Tok::Ident && ascii_iequals(t.value, "important");
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
