#include "casteljau/svg/xml_entities.h"

#include <algorithm>
#include <map>
#include <vector>

namespace casteljau {

namespace {

constexpr std::size_t npos = std::string_view::npos;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// XML's Name characters, non-ASCII ones taken whole (a UTF-8 byte >= 0x80).
bool is_name_start(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':' ||
           static_cast<unsigned char>(c) >= 0x80;
}
bool is_name_char(char c) {
    return is_name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
}

// The position just past `close` at or after i; npos when there is none.
std::size_t past(std::string_view s, std::size_t i, std::string_view close) {
    const std::size_t k = s.find(close, i);
    return k == npos ? npos : k + close.size();
}

// The name at i (empty when none starts there).
std::string_view name_at(std::string_view s, std::size_t i) {
    if (i >= s.size() || !is_name_start(s[i])) return {};
    std::size_t j = i + 1;
    while (j < s.size() && is_name_char(s[j])) ++j;
    return s.substr(i, j - i);
}

// The end of a markup declaration starting at i ("<!..."): past its '>',
// quoted literals skipped (they may hold '>'); npos when unterminated.
std::size_t declaration_end(std::string_view s, std::size_t i) {
    for (std::size_t k = i + 2; k < s.size(); ++k) {
        if (s[k] == '"' || s[k] == '\'') {
            k = s.find(s[k], k + 1);
            if (k == npos) return npos;
        } else if (s[k] == '>') {
            return k + 1;
        }
    }
    return npos;
}

struct Entity {
    std::string_view value; ///< the replacement text, as declared
    bool external = false;  ///< SYSTEM or PUBLIC: never read
};
using Entities = std::map<std::string_view, Entity, std::less<>>;

// One <!ENTITY ...> declaration [i, end): a general entity's name and value
// (the first declaration of a name binds, XML 1.0, 4.2); parameter
// entities are the DTD's own and are passed over.
void declare(std::string_view s, std::size_t i, std::size_t end, Entities& out) {
    std::size_t k = i + 8; // past "<!ENTITY"
    while (k < end && is_space(s[k])) ++k;
    if (k < end && s[k] == '%') return;
    const std::string_view name = name_at(s, k);
    if (name.empty()) return;
    k += name.size();
    while (k < end && is_space(s[k])) ++k;
    Entity e;
    if (k < end && (s[k] == '"' || s[k] == '\'')) {
        const std::size_t close = s.find(s[k], k + 1);
        if (close == npos || close >= end) return;
        e.value = s.substr(k + 1, close - k - 1);
    } else {
        e.external = true; // SYSTEM "uri" or PUBLIC "id" "uri"
    }
    out.emplace(name, e);
}

// The DOCTYPE before the root element, if any: its entities, and where the
// document's body (what follows it) starts; 0 when there is none.
std::size_t read_doctype(std::string_view s, Entities& entities) {
    std::size_t i = 0;
    if (s.substr(0, 3) == "\xEF\xBB\xBF") i = 3;
    while (i < s.size()) {
        if (is_space(s[i])) {
            ++i;
        } else if (s.compare(i, 2, "<?") == 0) {
            i = past(s, i, "?>");
        } else if (s.compare(i, 4, "<!--") == 0) {
            i = past(s, i, "-->");
        } else if (s.compare(i, 9, "<!DOCTYPE") == 0) {
            break;
        } else {
            return 0; // the root element, or text: no DOCTYPE
        }
        if (i == npos) return 0;
    }
    if (i >= s.size()) return 0;
    // The external ID's literals may hold '[' or '>'.
    std::size_t k = i + 9;
    for (; k < s.size() && s[k] != '[' && s[k] != '>'; ++k)
        if (s[k] == '"' || s[k] == '\'') {
            k = s.find(s[k], k + 1);
            if (k == npos) return 0;
        }
    if (k >= s.size()) return 0;
    if (s[k] == '>') return k + 1;
    // The internal subset: declarations, comments, processing instructions
    // and parameter-entity references, up to ']'.
    for (++k; k < s.size() && s[k] != ']';) {
        std::size_t next = k + 1;
        if (s.compare(k, 4, "<!--") == 0) {
            next = past(s, k, "-->");
        } else if (s.compare(k, 2, "<?") == 0) {
            next = past(s, k, "?>");
        } else if (s.compare(k, 2, "<!") == 0) {
            next = declaration_end(s, k);
            if (next != npos && s.compare(k, 8, "<!ENTITY") == 0) declare(s, k, next, entities);
        }
        if (next == npos) return 0; // malformed: pugixml says where
        k = next;
    }
    const std::size_t end = k < s.size() ? s.find('>', k) : npos;
    return end == npos ? 0 : end + 1;
}

// Copies a document's body, or a replacement text, into `out` with the
// references to declared entities replaced.
class Expander {
  public:
    Expander(const Entities& entities, std::size_t max_added, std::string& out)
        : entities_(entities), max_added_(max_added), out_(out) {}

    // Copies s; `body` when it is the document's (its comments, CDATA and
    // processing instructions are copied as they are), `at` the offset of
    // s in the document, or of the reference being expanded.
    bool copy(std::string_view s, bool body, std::size_t at) {
        for (std::size_t i = 0; i < s.size();) {
            const std::size_t k = s.find_first_of(body ? "<&" : "&", i);
            out_.append(s.substr(i, k == npos ? npos : k - i));
            if (k == npos) break;
            i = k;
            if (s[i] == '<') {
                std::size_t end = i + 1;
                if (s.compare(i, 4, "<!--") == 0)
                    end = past(s, i, "-->");
                else if (s.compare(i, 9, "<![CDATA[") == 0)
                    end = past(s, i, "]]>");
                else if (s.compare(i, 2, "<?") == 0)
                    end = past(s, i, "?>");
                if (end == npos) end = s.size(); // unterminated: pugixml says so
                out_.append(s.substr(i, end - i));
                i = end;
                continue;
            }
            const std::string_view name = name_at(s, i + 1);
            const std::size_t semi = i + 1 + name.size();
            const auto e = name.empty() || semi >= s.size() || s[semi] != ';'
                               ? entities_.end()
                               : entities_.find(name);
            if (e == entities_.end()) { // predefined, a character reference, or undeclared
                out_.push_back('&');
                ++i;
                continue;
            }
            if (!expand(e->first, e->second, body ? at + i : at)) return false;
            i = semi + 1;
        }
        return true;
    }

    std::string error;
    std::size_t offset = 0;

  private:
    bool expand(std::string_view name, const Entity& e, std::size_t at) {
        const auto fail = [&](std::string what) {
            error = std::move(what), offset = at;
            return false;
        };
        if (e.external)
            return fail("entity '" + std::string(name) +
                        "' is external (SYSTEM or PUBLIC), and external entities are not read");
        if (std::find(open_.begin(), open_.end(), name) != open_.end())
            return fail("entity '" + std::string(name) + "' refers to itself");
        if (int(open_.size()) >= kMaxEntityNesting)
            return fail("entities nested deeper than " + std::to_string(kMaxEntityNesting) +
                        " (the limit)");
        added_ += e.value.size();
        if (added_ > max_added_)
            return fail("entity references add more than " + std::to_string(max_added_) +
                        " bytes (the limit)");
        open_.push_back(name);
        const bool ok = copy(e.value, false, at);
        open_.pop_back();
        return ok;
    }

    const Entities& entities_;
    std::size_t max_added_, added_ = 0;
    std::string& out_;
    std::vector<std::string_view> open_; ///< the entities being expanded, outermost first
};

} // namespace

EntityExpansion expand_entities(std::string_view doc, std::size_t max_added) {
    EntityExpansion r;
    Entities entities;
    const std::size_t body = read_doctype(doc, entities);
    if (entities.empty()) return r;
    // Nothing to do unless the body refers to one of them.
    bool referred = false;
    for (std::size_t i = doc.find('&', body); i != npos && !referred; i = doc.find('&', i + 1)) {
        const std::string_view name = name_at(doc, i + 1);
        referred = !name.empty() && entities.count(name) > 0;
    }
    if (!referred) return r;
    r.text.reserve(doc.size());
    r.text.append(doc.substr(0, body));
    Expander x(entities, max_added, r.text);
    if (!x.copy(doc.substr(body), true, body)) {
        r.text.clear();
        r.error = std::move(x.error);
        r.offset = x.offset;
        return r;
    }
    r.changed = true;
    return r;
}

} // namespace casteljau
