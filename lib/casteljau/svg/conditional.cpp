#include "casteljau/svg/conditional.h"

#include <algorithm>
#include <cctype>

namespace casteljau {

namespace {

std::string lower_trimmed(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return out;
}

// `prefix` equals `tag`, or is followed in it by a '-'.
bool tag_prefix(std::string_view prefix, std::string_view tag) {
    return tag.substr(0, prefix.size()) == prefix &&
           (tag.size() == prefix.size() || tag[prefix.size()] == '-');
}

} // namespace

bool conditions_hold(const Conditions& c, std::span<const std::string> languages) {
    if (c.required_extensions) return false;
    if (!c.system_language) return true;
    std::string_view list = *c.system_language;
    while (!list.empty()) {
        const std::size_t comma = std::min(list.find(','), list.size());
        const std::string tag = lower_trimmed(list.substr(0, comma));
        list.remove_prefix(std::min(comma + 1, list.size()));
        if (tag.empty()) continue;
        for (const std::string& user : languages) {
            const std::string u = lower_trimmed(user);
            if (!u.empty() && (tag_prefix(u, tag) || tag_prefix(tag, u))) return true;
        }
    }
    return false;
}

} // namespace casteljau
