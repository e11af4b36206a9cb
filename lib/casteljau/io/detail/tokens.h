// Tokens of the patch text formats (.bpt, Quake 3 .map), with line numbers.
//
// Whitespace separates tokens; ( ) { } are tokens of their own; a "quoted
// string" is one token (quotes kept); // starts a comment to the end of the
// line. Errors are thrown as ReadError and become "file:line: what" at the
// reader's border (patch_read.cpp); nothing here allocates per token.
#pragma once

#include <string>
#include <string_view>

namespace casteljau::detail {

struct ReadError {
    int line;
    std::string what;
};

struct Token {
    std::string_view text;
    int line = 0;
};

class Tokens {
  public:
    explicit Tokens(std::string_view text) : text_(text) {}
    // False at the end of the text.
    bool next(Token& t);
    // The next token, or a ReadError saying that `what` was expected.
    Token expect(const char* what);
    // The next token, which must be exactly `text`.
    void expect_text(std::string_view text);
    // The next token as a finite number.
    double number(const char* what);
    // The next token as an integer in [lo, hi].
    int integer(const char* what, int lo, int hi);
    int line() const { return line_; }

  private:
    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 1;
};

// The whole of `s` as a finite double (decimal or scientific notation).
bool parse_finite(std::string_view s, double& out);

} // namespace casteljau::detail
