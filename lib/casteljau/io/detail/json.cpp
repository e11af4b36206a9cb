#include "casteljau/io/detail/json.h"

#include <algorithm>

namespace casteljau::detail {

namespace {

class Parser {
  public:
    explicit Parser(std::string_view s) : s_(s) {}

    JsonValue document() {
        JsonValue v = value(0);
        skip_space();
        if (pos_ != s_.size()) fail("unexpected text after the JSON value");
        return v;
    }

  private:
    [[noreturn]] void fail(const std::string& what) const { throw ReadError{line_, what}; }

    void skip_space() {
        while (pos_ < s_.size() &&
               (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\r' || s_[pos_] == '\n'))
            if (s_[pos_++] == '\n') ++line_;
    }
    char peek() {
        skip_space();
        if (pos_ >= s_.size()) fail("unexpected end of file");
        return s_[pos_];
    }
    void expect(char c) {
        if (peek() != c) fail(std::string("expected '") + c + "'");
        ++pos_;
    }

    JsonValue value(int depth) {
        if (depth > kMaxJsonDepth)
            fail("nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        const char c = peek();
        JsonValue v;
        v.line = line_;
        if (c == '{')
            object(v, depth);
        else if (c == '[')
            array(v, depth);
        else if (c == '"')
            v.kind = JsonValue::Kind::String, v.string = string();
        else if (literal("true"))
            v.kind = JsonValue::Kind::Bool, v.boolean = true;
        else if (literal("false"))
            v.kind = JsonValue::Kind::Bool;
        else if (literal("null"))
            v.kind = JsonValue::Kind::Null;
        else
            v.kind = JsonValue::Kind::Number, v.number = number();
        return v;
    }

    bool literal(std::string_view word) {
        if (s_.substr(pos_, word.size()) != word) return false;
        pos_ += word.size();
        return true;
    }

    void object(JsonValue& v, int depth) {
        v.kind = JsonValue::Kind::Object;
        expect('{');
        if (peek() == '}') return void(++pos_);
        for (;;) {
            if (peek() != '"') fail("expected a member name in quotes");
            std::string key = string();
            expect(':');
            v.keys.push_back(std::move(key));
            v.items.push_back(value(depth + 1));
            if (peek() == '}') return void(++pos_);
            expect(',');
        }
    }

    void array(JsonValue& v, int depth) {
        v.kind = JsonValue::Kind::Array;
        expect('[');
        if (peek() == ']') return void(++pos_);
        for (;;) {
            v.items.push_back(value(depth + 1));
            if (peek() == ']') return void(++pos_);
            expect(',');
        }
    }

    // Strings as the scene format needs them: escapes are kept verbatim
    // except \" and \\, which is all a member name or type ever holds.
    std::string string() {
        ++pos_; // the opening quote
        std::string out;
        while (pos_ < s_.size() && s_[pos_] != '"') {
            if (s_[pos_] == '\n' || static_cast<unsigned char>(s_[pos_]) < 0x20)
                fail("control character in a string");
            if (s_[pos_] == '\\' && pos_ + 1 < s_.size()) ++pos_;
            out += s_[pos_++];
        }
        if (pos_ >= s_.size()) fail("unterminated string");
        ++pos_;
        return out;
    }

    // The JSON number grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
    double number() {
        const std::size_t start = pos_;
        const auto digits = [&] {
            const std::size_t from = pos_;
            while (pos_ < s_.size() && s_[pos_] >= '0' && s_[pos_] <= '9') ++pos_;
            return pos_ > from;
        };
        if (pos_ < s_.size() && s_[pos_] == '-') ++pos_;
        bool ok = digits();
        if (ok && pos_ < s_.size() && s_[pos_] == '.') ++pos_, ok = digits();
        if (ok && pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
            ++pos_;
            if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
            ok = digits();
        }
        const std::string_view text = s_.substr(start, std::max(pos_, start + 1) - start);
        double v = 0;
        if (!ok || !parse_finite(text, v))
            fail("'" + std::string(text.substr(0, 40)) + "' is not a finite JSON number");
        return v;
    }

    std::string_view s_;
    std::size_t pos_ = 0;
    int line_ = 1;
};

} // namespace

const JsonValue* JsonValue::find(std::string_view key) const {
    for (std::size_t i = 0; i < keys.size(); ++i)
        if (keys[i] == key) return &items[i];
    return nullptr;
}

JsonValue parse_json(std::string_view text) { return Parser(text).document(); }

} // namespace casteljau::detail
