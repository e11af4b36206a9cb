#include "casteljau/io/detail/tokens.h"

#include <charconv>
#include <cmath>

namespace casteljau::detail {

namespace {

std::string quoted(std::string_view s) {
    constexpr std::size_t kShown = 40; // enough to recognise, short enough for one line
    // Appended, not concatenated: GCC 12 warns falsely (-Wrestrict, PR 105329)
    // on operator+ chains that start with a literal.
    std::string out(1, '\'');
    out.append(s.substr(0, kShown)).append(s.size() > kShown ? "...'" : "'");
    return out;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f'; }
bool is_bracket(char c) { return c == '(' || c == ')' || c == '{' || c == '}'; }

} // namespace

bool parse_finite(std::string_view s, double& out) {
    if (!s.empty() && s[0] == '+') s.remove_prefix(1); // from_chars takes no '+'
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
}

bool Tokens::next(Token& t) {
    for (;;) {
        while (pos_ < text_.size() && is_space(text_[pos_]))
            if (text_[pos_++] == '\n') ++line_;
        if (pos_ + 1 < text_.size() && text_[pos_] == '/' && text_[pos_ + 1] == '/') {
            while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
            continue;
        }
        break;
    }
    if (pos_ >= text_.size()) return false;
    const std::size_t start = pos_;
    t.line = line_;
    if (is_bracket(text_[pos_])) {
        ++pos_;
    } else if (text_[pos_] == '"') {
        const std::size_t close = text_.find('"', pos_ + 1);
        if (close == std::string_view::npos ||
            text_.substr(pos_, close - pos_).find('\n') != std::string_view::npos)
            throw ReadError{line_, "unterminated string"};
        pos_ = close + 1;
    } else {
        while (pos_ < text_.size() && !is_space(text_[pos_]) && !is_bracket(text_[pos_]) &&
               text_[pos_] != '"')
            ++pos_;
    }
    t.text = text_.substr(start, pos_ - start);
    return true;
}

Token Tokens::expect(const char* what) {
    Token t;
    if (!next(t)) throw ReadError{line_, std::string("unexpected end of file, expected ") + what};
    return t;
}

void Tokens::expect_text(std::string_view text) {
    const std::string what = quoted(text);
    const Token t = expect(what.c_str());
    if (t.text != text) throw ReadError{t.line, "expected " + what + ", found " + quoted(t.text)};
}

double Tokens::number(const char* what) {
    const Token t = expect(what);
    double v;
    if (!parse_finite(t.text, v))
        throw ReadError{t.line,
                        std::string(what) + ": " + quoted(t.text) + " is not a finite number"};
    return v;
}

int Tokens::integer(const char* what, int lo, int hi) {
    const Token t = expect(what);
    int v = 0;
    const auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (ec != std::errc() || end != t.text.data() + t.text.size())
        throw ReadError{t.line, std::string(what) + ": " + quoted(t.text) + " is not an integer"};
    if (v < lo || v > hi)
        throw ReadError{t.line, std::string(what) + ": " + std::to_string(v) + " is not in " +
                                    std::to_string(lo) + ".." + std::to_string(hi)};
    return v;
}

} // namespace casteljau::detail
