#include "casteljau/svg/xml_entities.h"

#include "casteljau/svg/detail/ascii.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <vector>

namespace casteljau {

namespace {

constexpr std::size_t npos = std::string_view::npos;

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
    std::string value;     ///< the replacement text, its character references decoded
    bool external = false; ///< SYSTEM or PUBLIC: never read
};
using Entities = std::map<std::string_view, Entity, std::less<>>;

// Appends code point c as UTF-8.
void append_utf8(std::string& out, std::uint32_t c) {
    if (c < 0x80) {
        out.push_back(char(c));
    } else if (c < 0x800) {
        out.push_back(char(0xC0 | c >> 6));
        out.push_back(char(0x80 | (c & 0x3F)));
    } else if (c < 0x10000) {
        out.push_back(char(0xE0 | c >> 12));
        out.push_back(char(0x80 | (c >> 6 & 0x3F)));
        out.push_back(char(0x80 | (c & 0x3F)));
    } else {
        out.push_back(char(0xF0 | c >> 18));
        out.push_back(char(0x80 | (c >> 12 & 0x3F)));
        out.push_back(char(0x80 | (c >> 6 & 0x3F)));
        out.push_back(char(0x80 | (c & 0x3F)));
    }
}

// A literal entity value with its character references replaced, as XML
// does when the entity is declared (4.5): <!ENTITY lt "&#38;#60;"> stands
// for "&#60;". A reference that is not a valid character stays as written.
std::string decode_char_refs(std::string_view v) {
    std::string out;
    for (std::size_t i = 0; i < v.size();) {
        const std::size_t semi = v.compare(i, 2, "&#") == 0 ? v.find(';', i) : npos;
        std::uint32_t c = 0;
        bool ok = semi != npos && semi > i + 2 && semi - i <= 12;
        const bool hex = ok && v[i + 2] == 'x';
        for (std::size_t k = i + (hex ? 3 : 2); ok && k < semi; ++k) {
            const char d = v[k];
            const int digit = d >= '0' && d <= '9'          ? d - '0'
                              : hex && d >= 'a' && d <= 'f' ? d - 'a' + 10
                              : hex && d >= 'A' && d <= 'F' ? d - 'A' + 10
                                                            : -1;
            ok = digit >= 0 && c < 0x110000;
            c = c * (hex ? 16 : 10) + std::uint32_t(std::max(digit, 0));
        }
        ok = ok && (!hex || semi > i + 3) && c > 0 && c < 0x110000 && !(c >= 0xD800 && c < 0xE000);
        if (!ok) {
            out.push_back(v[i++]);
            continue;
        }
        append_utf8(out, c);
        i = semi + 1;
    }
    return out;
}

// One <!ENTITY ...> declaration [i, end): a general entity's name and value
// (the first declaration of a name binds, XML 1.0, 4.2). Parameter entities
// are the DTD's own and are passed over, and so are declarations of the
// predefined five (4.6 allows them; they keep their meaning, pugixml's).
void declare(std::string_view s, std::size_t i, std::size_t end, Entities& out) {
    std::size_t k = i + 8; // past "<!ENTITY"
    while (k < end && svg_detail::is_xml_space(s[k])) ++k;
    if (k < end && s[k] == '%') return;
    const std::string_view name = name_at(s, k);
    if (name.empty() || name == "lt" || name == "gt" || name == "amp" || name == "apos" ||
        name == "quot")
        return;
    k += name.size();
    while (k < end && svg_detail::is_xml_space(s[k])) ++k;
    Entity e;
    if (k < end && (s[k] == '"' || s[k] == '\'')) {
        const std::size_t close = s.find(s[k], k + 1);
        if (close == npos || close >= end) return;
        e.value = decode_char_refs(s.substr(k + 1, close - k - 1));
    } else {
        e.external = true; // SYSTEM "uri" or PUBLIC "id" "uri"
    }
    out.emplace(name, std::move(e));
}

// The DOCTYPE before the root element, if any: its entities, and where the
// document's body (what follows it) starts; 0 when there is none, or when it
// is malformed (then it declares nothing here, and pugixml says where).
std::size_t read_doctype(std::string_view s, Entities& entities) {
    std::size_t i = 0;
    if (s.substr(0, 3) == "\xEF\xBB\xBF") i = 3;
    while (i < s.size()) {
        if (svg_detail::is_xml_space(s[i])) {
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
        if (next == npos) {
            entities.clear();
            return 0;
        }
        k = next;
    }
    const std::size_t end = k < s.size() ? s.find('>', k) : npos;
    if (end == npos) {
        entities.clear();
        return 0;
    }
    return end + 1;
}

// Copies a document's body, or a replacement text, into `out` with the
// references to declared entities replaced.
class Expander {
  public:
    Expander(const Entities& entities, std::size_t max_added, std::string& out)
        : entities_(entities), max_added_(max_added), out_(out) {}

    // Where a text is copied: the document's body (comments, CDATA,
    // processing instructions and tags told apart), an element's content,
    // or an attribute value, where a replacement text's quotes and '<' are
    // data (XML 1.0, 4.4.5) and so are escaped for pugixml.
    enum class Mode { Body, Content, Attribute };

    // Copies s, at offset `at` of the document (or of the reference being
    // expanded, for a replacement text).
    bool copy(std::string_view s, Mode mode, std::size_t at) {
        for (std::size_t i = 0; i < s.size();) {
            const std::size_t k = s.find_first_of(mode == Mode::Body ? "<&" : "&", i);
            append(s.substr(i, k == npos ? npos : k - i), mode);
            if (k == npos) break;
            i = k;
            if (s[i] == '<') {
                std::size_t end = npos;
                if (s.compare(i, 4, "<!--") == 0)
                    end = past(s, i, "-->");
                else if (s.compare(i, 9, "<![CDATA[") == 0)
                    end = past(s, i, "]]>");
                else if (s.compare(i, 2, "<?") == 0 || s.compare(i, 2, "<!") == 0)
                    end = past(s, i, ">");
                else if (!tag(s, i, at)) // a start or end tag: i is past it
                    return false;
                else
                    continue;
                if (end == npos) end = s.size(); // unterminated: pugixml says so
                out_.append(s.substr(i, end - i));
                i = end;
                continue;
            }
            if (!reference(s, i, mode == Mode::Attribute ? Mode::Attribute : Mode::Content, at))
                return false;
        }
        return true;
    }

    std::string error;
    std::size_t offset = 0;

  private:
    void append(std::string_view t, Mode mode) {
        if (mode != Mode::Attribute) return void(out_.append(t));
        for (const char c : t)
            out_.append(c == '"'    ? "&quot;"
                        : c == '\'' ? "&apos;"
                        : c == '<'  ? "&lt;"
                                    : std::string(1, c));
    }

    // Copies the tag at i ("<name ...>"), expanding references inside its
    // quoted attribute values; leaves i past it.
    bool tag(std::string_view s, std::size_t& i, std::size_t at) {
        char quote = 0;
        out_.push_back('<');
        for (++i; i < s.size();) {
            const char c = s[i];
            if (quote && c == '&') {
                if (!reference(s, i, Mode::Attribute, at)) return false;
                continue;
            }
            out_.push_back(c);
            ++i;
            if (quote) {
                if (c == quote) quote = 0;
            } else if (c == '"' || c == '\'') {
                quote = c;
            } else if (c == '>') {
                break;
            }
        }
        return true;
    }

    // The reference at s[i] == '&': a declared entity's replacement, or '&'
    // as it is (a predefined entity, a character reference, a name declared
    // nowhere); leaves i past what it took.
    bool reference(std::string_view s, std::size_t& i, Mode mode, std::size_t at) {
        const std::string_view name = name_at(s, i + 1);
        const std::size_t semi = i + 1 + name.size();
        const auto e = name.empty() || semi >= s.size() || s[semi] != ';' ? entities_.end()
                                                                          : entities_.find(name);
        if (e == entities_.end()) {
            out_.push_back('&');
            ++i;
            return true;
        }
        if (!expand(e->first, e->second, open_.empty() ? at + i : at, mode)) return false;
        i = semi + 1;
        return true;
    }

    bool expand(std::string_view name, const Entity& e, std::size_t at, Mode mode) {
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
        const bool ok = copy(e.value, mode, at);
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
    r.doctype = body > 0;
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
    if (!x.copy(doc.substr(body), Expander::Mode::Body, body)) {
        r.text.clear();
        r.error = std::move(x.error);
        r.offset = x.offset;
        return r;
    }
    r.changed = true;
    return r;
}

} // namespace casteljau
