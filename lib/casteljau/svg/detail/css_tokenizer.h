// Internal to the CSS style sheets (not installed): the tokenizer of CSS
// Syntax 3, 4, which css.cpp's rule and declaration parser reads.
//
// Tokens: as 4.3 defines them, with two simplifications that change no
// valid sheet: the input is taken as UTF-8 bytes (a non-ASCII byte is a name
// character, as every non-ASCII code point is, 4.2), and a NUL byte is kept
// rather than replaced by U+FFFD. Comments produce no token (4.3.2); the gap
// they leave between two tokens' offsets is kept when a value is serialized.
#pragma once

#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/detail/css_selector.h"
#include "casteljau/text/utf8.h"

#include <string>
#include <string_view>
#include <vector>

namespace casteljau::css_detail {

// The code point classes of 4.2 (on bytes: see above).
inline bool is_digit(int c) { return c >= '0' && c <= '9'; }
inline bool is_hex(int c) { return is_digit(c) || ((c | 0x20) >= 'a' && (c | 0x20) <= 'f'); }
inline bool is_newline(int c) { return c == '\n' || c == '\r' || c == '\f'; }
inline bool is_space(int c) { return c == ' ' || c == '\t' || is_newline(c); }
inline bool is_name_start(int c) {
    return ((c | 0x20) >= 'a' && (c | 0x20) <= 'z') || c == '_' || c >= 0x80;
}
inline bool is_name(int c) { return is_name_start(c) || is_digit(c) || c == '-'; }
inline bool is_non_printable(int c) {
    return (c >= 0 && c <= 8) || c == 0x0b || (c >= 0x0e && c <= 0x1f) || c == 0x7f;
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
        if (!svg_detail::iequals(t.value, "url")) return;
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

} // namespace casteljau::css_detail
