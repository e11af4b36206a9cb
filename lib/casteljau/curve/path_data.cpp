#include "casteljau/curve/path_data.h"

#include "casteljau/curve/arc.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace casteljau {

namespace {

bool is_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

class Parser {
  public:
    explicit Parser(std::string_view s) : s_(s) {}

    PathDataResult run() {
        skip_wsp();
        if (at_end()) return finish();
        if (s_[pos_] != 'M' && s_[pos_] != 'm') fail("path data must begin with a moveto (M or m)");
        while (!error_) {
            skip_wsp();
            if (at_end()) break;
            const std::size_t cmd_pos = pos_;
            const char cmd = s_[pos_++];
            if (!command(cmd)) {
                if (!error_) fail_at(cmd_pos, std::string("unknown command '") + cmd + "'");
            }
        }
        return finish();
    }

  private:
    PathDataResult finish() { return {std::move(path_), std::move(error_)}; }
    bool at_end() const { return pos_ >= s_.size(); }
    void fail(std::string msg) { fail_at(pos_, std::move(msg)); }
    void fail_at(std::size_t at, std::string msg) {
        if (!error_) error_ = PathDataError{at, std::move(msg)};
    }
    void skip_wsp() {
        while (!at_end() && is_wsp(s_[pos_])) ++pos_;
    }
    void skip_comma_wsp() {
        skip_wsp();
        if (!at_end() && s_[pos_] == ',') {
            ++pos_;
            skip_wsp();
        }
    }
    // True when the next token starts a number (so a command repeats). A
    // comma promises another argument: a comma before anything else is an error.
    bool number_follows() {
        skip_wsp();
        const bool comma = !at_end() && s_[pos_] == ',';
        if (comma) ++pos_;
        skip_wsp();
        const char c = at_end() ? '\0' : s_[pos_];
        const bool number = is_digit(c) || c == '.' || c == '-' || c == '+';
        if (comma && !number) fail("expected a number after ','");
        return number;
    }

    // number ::= sign? (digits ("." digits?)? | "." digits) exponent?
    bool number(double& out) {
        skip_comma_wsp();
        const std::size_t begin = pos_;
        std::size_t i = pos_;
        if (i < s_.size() && (s_[i] == '+' || s_[i] == '-')) ++i;
        const std::size_t int_begin = i;
        while (i < s_.size() && is_digit(s_[i])) ++i;
        bool digits = i > int_begin;
        if (i < s_.size() && s_[i] == '.') {
            const std::size_t frac_begin = ++i;
            while (i < s_.size() && is_digit(s_[i])) ++i;
            digits = digits || i > frac_begin;
        }
        if (!digits) {
            fail_at(begin, at_end() ? "expected a number, found the end of the data"
                                    : std::string("expected a number, found '") + s_[begin] + "'");
            return false;
        }
        if (i < s_.size() && (s_[i] == 'e' || s_[i] == 'E')) {
            std::size_t j = i + 1;
            if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
            const std::size_t exp_begin = j;
            while (j < s_.size() && is_digit(s_[j])) ++j;
            if (j == exp_begin) {
                fail_at(i, "exponent without digits");
                return false;
            }
            i = j;
        }
        // from_chars rejects a leading '+', which the grammar allows.
        const std::size_t parse_begin = s_[begin] == '+' ? begin + 1 : begin;
        const std::string_view token = s_.substr(begin, i - begin);
        auto [end, ec] = std::from_chars(s_.data() + parse_begin, s_.data() + i, out);
        // Too small to represent is zero (as every SVG renderer reads it); too
        // large is an error: infinities never enter a path.
        const bool underflow = ec == std::errc::result_out_of_range &&
                               (token.find("e-") != token.npos || token.find("E-") != token.npos);
        if (underflow) out = 0.0, ec = std::errc(), end = s_.data() + i;
        if (ec != std::errc() || end != s_.data() + i || !std::isfinite(out)) {
            fail_at(begin, "number '" + std::string(token) + "' is out of range");
            return false;
        }
        pos_ = i;
        return true;
    }

    bool flag(bool& out) {
        skip_comma_wsp();
        if (!at_end() && (s_[pos_] == '0' || s_[pos_] == '1')) {
            out = s_[pos_++] == '1';
            return true;
        }
        fail("expected an arc flag (0 or 1)");
        return false;
    }

    bool point(bool relative, Point& out) {
        double x, y;
        skip_comma_wsp();
        const std::size_t at = pos_;
        if (!number(x) || !number(y)) return false;
        out = relative ? path_.current_point() + Vec2{x, y} : Point{x, y};
        return finite(at, out);
    }

    // Relative coordinates, H/V steps and S/T reflections add numbers that
    // are each finite but may sum past the double range: that is an error at
    // `at`, never an infinity in the path.
    bool finite(std::size_t at, Point p) {
        if (std::isfinite(p.x) && std::isfinite(p.y)) return true;
        fail_at(at, "coordinates overflow the double range");
        return false;
    }

    // The arc's centre form (arc.h), checked before Path::arc_to builds its
    // conics: with radii near the double range, or so small that their
    // squares vanish, it is not representable. The conics' control points lie
    // within sqrt(2) radii of the centre (a 90-degree piece's middle control
    // point is at r / cos 45deg), so 2 radii beyond it must stay finite.
    bool representable_arc(std::size_t at, const SvgArcInput& in) {
        const EllipseArc a = svg_arc(in);
        if (a.kind != EllipseArc::Kind::Arc) return true;
        const double reach = 2 * std::max(a.radii.x, a.radii.y);
        const bool ok = std::isfinite(a.theta1) && std::isfinite(a.dtheta) &&
                        std::isfinite(std::fabs(a.center.x) + reach) &&
                        std::isfinite(std::fabs(a.center.y) + reach);
        if (!ok) fail_at(at, "the arc's ellipse is outside the double range");
        return ok;
    }

    // One command letter and all its (implicitly repeated) argument groups.
    bool command(char cmd) {
        const bool rel = cmd >= 'a' && cmd <= 'z';
        const char up = rel ? char(cmd - 'a' + 'A') : cmd;
        if (up == 'Z') {
            path_.close();
            last_ = 'Z';
            return true;
        }
        if (std::string_view("MLHVCSQTA").find(up) == std::string_view::npos) return false;
        bool first = true;
        do {
            if (!segment(up, rel, first)) return true; // error_ is set
            first = false;
        } while (number_follows());
        return true;
    }

    bool segment(char up, bool rel, bool first) {
        skip_comma_wsp();
        const std::size_t at = pos_; // where this argument group begins
        const Point cur = path_.current_point();
        Point p, c1, c2;
        double v;
        switch (up) {
        case 'M':
            if (!point(rel, p)) return false;
            // Extra pairs after a moveto are implicit linetos.
            first ? path_.move_to(p) : path_.line_to(p);
            break;
        case 'L':
            if (!point(rel, p)) return false;
            path_.line_to(p);
            break;
        case 'H':
            if (!number(v)) return false;
            p = {rel ? cur.x + v : v, cur.y};
            if (!finite(at, p)) return false;
            path_.line_to(p);
            break;
        case 'V':
            if (!number(v)) return false;
            p = {cur.x, rel ? cur.y + v : v};
            if (!finite(at, p)) return false;
            path_.line_to(p);
            break;
        case 'C':
            if (!point(rel, c1) || !point(rel, c2) || !point(rel, p)) return false;
            path_.cubic_to(c1, c2, p);
            ctrl_ = c2;
            break;
        case 'S':
            if (!point(rel, c2) || !point(rel, p)) return false;
            c1 = (last_ == 'C' || last_ == 'S') ? cur + (cur - ctrl_) : cur;
            if (!finite(at, c1)) return false;
            path_.cubic_to(c1, c2, p);
            ctrl_ = c2;
            break;
        case 'Q':
            if (!point(rel, c1) || !point(rel, p)) return false;
            path_.quad_to(c1, p);
            ctrl_ = c1;
            break;
        case 'T':
            if (!point(rel, p)) return false;
            c1 = (last_ == 'Q' || last_ == 'T') ? cur + (cur - ctrl_) : cur;
            if (!finite(at, c1)) return false;
            path_.quad_to(c1, p);
            ctrl_ = c1;
            break;
        case 'A': {
            double rx, ry, rot;
            bool large, sweep;
            if (!number(rx) || !number(ry) || !number(rot) || !flag(large) || !flag(sweep) ||
                !point(rel, p))
                return false;
            if (!representable_arc(at, {cur, p, {rx, ry}, rot, large, sweep})) return false;
            path_.arc_to({rx, ry}, rot, large, sweep, p);
            break;
        }
        }
        last_ = up;
        return true;
    }

    std::string_view s_;
    std::size_t pos_ = 0;
    Path path_;
    std::optional<PathDataError> error_;
    char last_ = 0; // previous command (upper case), for S and T reflection
    Point ctrl_;    // its last control point
};

} // namespace

PathDataResult parse_path_data(std::string_view data) { return Parser(data).run(); }

} // namespace casteljau
