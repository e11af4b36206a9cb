// Resolving <image> hrefs: data: URLs and local files.
//
// URL text is cleaned as the URL Standard's parser does (WHATWG URL, 4.4):
// leading and trailing C0 controls and spaces are dropped, and tabs and
// newlines are removed everywhere, so an href wrapped over lines still works.
//
// data: URLs (RFC 2397; decoded as WHATWG Fetch's "data: URL processor",
// 4.5, does): `data:[<mediatype>][;base64],<data>`. The data is
// percent-decoded (a '%' not followed by two hex digits stays as it is), then,
// with ";base64", decoded by Infra's "forgiving-base64 decode" (4.6): ASCII
// whitespace removed; when the length is a multiple of 4, one or two final
// '=' removed; then a length of 4k + 1, or any character outside A-Z a-z 0-9
// + /, is an error; the bits left over at the end are dropped.
//
// Files: a reference with a scheme (RFC 3986 3.1: a letter, then letters,
// digits, '+', '-', '.', then ':') other than file:, or with a host other
// than localhost (a "//host" prefix), would need the network: refused. The
// path is percent-decoded, made absolute against the SVG's folder,
// canonicalised (symlinks resolved, so a link cannot lead outside), and
// accepted only if it lies within the canonical SVG folder or resources
// directory, compared component by component: /a/bc is not within /a/b.
#include "casteljau/svg/resource_url.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace casteljau {

namespace fs = std::filesystem;

namespace {

char lower(char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; }

/// Whether `s` starts with `prefix` (lowercase), in any case.
bool starts_with_ci(std::string_view s, std::string_view prefix) {
    return s.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), s.begin(),
                                                   [](char p, char c) { return p == lower(c); });
}

bool equals_ci(std::string_view s, std::string_view lowercase) {
    return s.size() == lowercase.size() && starts_with_ci(s, lowercase);
}

bool is_ascii_whitespace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\f' || c == '\r';
}

std::string_view trim_spaces(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
}

/// The URL text as the URL parser sees it (see above).
std::string url_text(std::string_view s) {
    const auto c0_or_space = [](char c) { return static_cast<unsigned char>(c) <= 0x20; };
    while (!s.empty() && c0_or_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && c0_or_space(s.back())) s.remove_suffix(1);
    std::string out;
    for (char c : s)
        if (c != '\t' && c != '\n' && c != '\r') out += c;
    return out;
}

int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::string percent_decode(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        const int hi = s[i] == '%' && i + 2 < s.size() ? hex_value(s[i + 1]) : -1;
        const int lo = hi >= 0 ? hex_value(s[i + 2]) : -1;
        if (lo >= 0) {
            out += char(hi * 16 + lo);
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

int base64_value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

/// Infra's forgiving-base64 decode (see above); false on an error.
bool forgiving_base64(std::string_view in, std::vector<unsigned char>& out) {
    std::string data;
    for (char c : in)
        if (!is_ascii_whitespace(c)) data += c;
    if (data.size() % 4 == 0 && data.ends_with('=')) {
        data.pop_back();
        if (data.ends_with('=')) data.pop_back();
    }
    if (data.size() % 4 == 1) return false;
    unsigned acc = 0;
    int bits = 0;
    for (char c : data) {
        const int v = base64_value(c);
        if (v < 0) return false;
        acc = (acc << 6 | unsigned(v)) & 0xffffff;
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<unsigned char>(acc >> bits));
        }
    }
    return true;
}

/// The length of the scheme `s` starts with (RFC 3986 3.1), or 0 if none.
std::size_t scheme_length(std::string_view s) {
    const auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
    if (s.empty() || !alpha(s[0])) return 0;
    std::size_t i = 1;
    while (i < s.size() && (alpha(s[i]) || (s[i] >= '0' && s[i] <= '9') || s[i] == '+' ||
                            s[i] == '-' || s[i] == '.'))
        ++i;
    return i < s.size() && s[i] == ':' ? i : 0;
}

/// `href` for a message: quoted, and cut when long.
std::string quoted(std::string_view href) {
    constexpr std::size_t kMax = 80;
    // Appended, not "'" + std::string(...): GCC 12 at -O3 warns (-Wrestrict)
    // about a false overlap in that operator+.
    std::string q(1, '\'');
    q.append(href.substr(0, kMax));
    q += href.size() > kMax ? "...'" : "'";
    return q;
}

/// Whether canonical path `p` is `root` or lies below it.
bool within(const fs::path& p, const fs::path& root) {
    return std::mismatch(root.begin(), root.end(), p.begin(), p.end()).first == root.end();
}

} // namespace

std::optional<DataUrl> parse_data_url(std::string_view url, std::string& error) {
    error.clear();
    const std::string text = url_text(url);
    if (!starts_with_ci(text, "data:")) return std::nullopt;
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos) {
        error = "data: URL without a comma before its data";
        return std::nullopt;
    }
    std::string_view meta = trim_spaces(std::string_view(text).substr(5, comma - 5));
    // ";base64" ends the media type, in any case, spaces allowed before it.
    bool base64 = false;
    if (meta.size() >= 6 && starts_with_ci(meta.substr(meta.size() - 6), "base64")) {
        const std::string_view rest = trim_spaces(meta.substr(0, meta.size() - 6));
        if (rest.ends_with(';')) {
            base64 = true;
            meta = rest.substr(0, rest.size() - 1);
        }
    }
    DataUrl d;
    const std::string type = percent_decode(meta.substr(0, meta.find(';')));
    for (char c : trim_spaces(type)) d.mime += lower(c);
    if (d.mime.empty()) d.mime = "text/plain";
    const std::string body = percent_decode(std::string_view(text).substr(comma + 1));
    if (!base64) {
        d.bytes.assign(body.begin(), body.end());
    } else if (!forgiving_base64(body, d.bytes)) {
        error = "data: URL with invalid base64 data";
        return std::nullopt;
    }
    return d;
}

ResourcePath resolve_resource_path(std::string_view href, const std::string& svg_dir,
                                   const std::string& resources_dir, const std::string& root_dir) {
    const std::string text = url_text(href);
    std::string_view ref = std::string_view(text).substr(0, text.find_first_of("?#"));
    const auto network = [&] {
        return ResourcePath{"", quoted(href) + ": network access is not allowed"};
    };
    if (const std::size_t n = scheme_length(ref)) {
        if (!equals_ci(ref.substr(0, n), "file")) return network();
        ref.remove_prefix(5);
        if (ref.starts_with("//")) { // file://host/path: only the local host
            const std::size_t slash = std::min(ref.find('/', 2), ref.size());
            const std::string_view host = ref.substr(2, slash - 2);
            if (!host.empty() && !equals_ci(host, "localhost")) return network();
            ref = slash < ref.size() ? ref.substr(slash) : "/";
        }
    } else if (ref.starts_with("//")) {
        return network();
    }
    const std::string decoded = percent_decode(ref);
    if (decoded.empty()) return {"", quoted(href) + ": refers to no file"};
    if (decoded.find('\0') != std::string::npos)
        return {"", quoted(href) + ": a file name cannot contain a NUL character"};
    std::error_code ec;
    const fs::path dir = svg_dir.empty() ? fs::current_path(ec) : fs::path(svg_dir);
    fs::path p(decoded);
    if (p.is_relative()) p = dir / p;
    const fs::path target = fs::weakly_canonical(p, ec);
    if (ec) return {"", quoted(href) + ": cannot resolve: " + ec.message()};
    // A folder that does not exist has nothing within it.
    const auto inside = [&](const std::string& folder) {
        std::error_code root_ec;
        const fs::path root = fs::canonical(folder, root_ec);
        return !root_ec && within(target, root);
    };
    if (!inside(root_dir.empty() ? dir.string() : root_dir) &&
        (resources_dir.empty() || !inside(resources_dir)))
        return {"", quoted(href) + ": outside the SVG's folder and the resources directory"};
    return {target.string(), ""};
}

} // namespace casteljau
