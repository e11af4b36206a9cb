#include "casteljau/svg/xml_encoding.h"

#include "casteljau/svg/detail/ascii.h"

#include <algorithm>
#include <cerrno>
#include <iconv.h>
#include <initializer_list>

namespace casteljau {

namespace {

// Where the XML declaration's encoding label stands in `text`, or npos: the
// declaration is the text's very start (XML 1.0, 2.8), and its pseudo-
// attributes are ASCII.
struct Span {
    std::size_t pos = std::string_view::npos, len = 0;
};
Span declared_label(std::string_view text) {
    using svg_detail::is_xml_space;
    if (!text.starts_with("<?xml") || text.size() < 6 || !is_xml_space(text[5])) return {};
    const std::string_view decl = text.substr(0, text.find("?>"));
    std::size_t k = decl.find("encoding");
    if (k == std::string_view::npos) return {};
    k += 8;
    while (k < decl.size() && is_xml_space(decl[k])) ++k;
    if (k >= decl.size() || decl[k] != '=') return {};
    ++k;
    while (k < decl.size() && is_xml_space(decl[k])) ++k;
    if (k >= decl.size() || (decl[k] != '"' && decl[k] != '\'')) return {};
    const std::size_t end = decl.find(decl[k], k + 1);
    if (end == std::string_view::npos) return {};
    return {k + 1, end - k - 1};
}

// The decoder browsers use for a label (the WHATWG Encoding Standard, 4.2:
// its labels of a few encodings, as iconv names them), "" for UTF-8, or the
// label itself for iconv to know or not.
std::string decoder_for(std::string label) {
    std::transform(label.begin(), label.end(), label.begin(),
                   [](unsigned char c) { return char(c >= 'A' && c <= 'Z' ? c + 32 : c); });
    const auto in = [&](std::initializer_list<std::string_view> labels) {
        return std::find(labels.begin(), labels.end(), label) != labels.end();
    };
    // A UTF-16 label on a text that is not UTF-16 (no zero bytes, checked
    // first): read as UTF-8, as the standard's decoding does.
    if (in({"utf-8", "utf8", "unicode-1-1-utf-8", "utf-16", "utf-16le", "utf-16be"})) return "";
    if (in({"iso-8859-1", "iso8859-1", "iso_8859-1", "iso_8859-1:1987", "iso88591", "latin1", "l1",
            "us-ascii", "ascii", "ansi_x3.4-1968", "cp1252", "windows-1252", "x-cp1252", "cp819",
            "ibm819", "iso-ir-100", "csisolatin1"}))
        return "WINDOWS-1252";
    if (in({"shift_jis", "sjis", "ms_kanji", "ms932", "windows-31j", "x-sjis", "csshiftjis"}))
        return "CP932";
    if (in({"gb2312", "gbk", "chinese", "csgb2312", "x-gbk", "gb_2312", "gb_2312-80", "iso-ir-58",
            "csiso58gb231280"}))
        return "GBK";
    if (in({"big5", "big5-hkscs", "cn-big5", "csbig5", "x-x-big5"})) return "BIG5-HKSCS";
    if (in({"euc-kr", "korean", "ks_c_5601-1987", "ks_c_5601-1989", "ksc5601", "ksc_5601",
            "windows-949", "csksc56011987", "iso-ir-149"}))
        return "CP949";
    return label;
}

// The encoding of a text in UTF-16 or UTF-32 (XML 1.0, appendix F: a byte
// order mark, or '<' in two or four bytes), the mark's length in `skip`;
// "" for any other text.
const char* wide_encoding(std::string_view t, std::size_t& skip) {
    const auto starts = [&](std::initializer_list<unsigned char> bytes) {
        if (t.size() < bytes.size()) return false;
        std::size_t i = 0;
        for (unsigned char b : bytes)
            if (static_cast<unsigned char>(t[i++]) != b) return false;
        return true;
    };
    skip = 4;
    if (starts({0x00, 0x00, 0xFE, 0xFF})) return "UTF-32BE";
    if (starts({0xFF, 0xFE, 0x00, 0x00})) return "UTF-32LE";
    skip = 2;
    if (starts({0xFE, 0xFF})) return "UTF-16BE";
    if (starts({0xFF, 0xFE})) return "UTF-16LE";
    skip = 0;
    if (starts({0x00, 0x00, 0x00, 0x3C})) return "UTF-32BE";
    if (starts({0x3C, 0x00, 0x00, 0x00})) return "UTF-32LE";
    if (starts({0x00, 0x3C, 0x00, 0x3F})) return "UTF-16BE";
    if (starts({0x3C, 0x00, 0x3F, 0x00})) return "UTF-16LE";
    return "";
}

// `in` decoded from `from` into `out`, up to max_bytes (false beyond).
bool decode(iconv_t cd, std::string_view in, const std::string& from, std::size_t max_bytes,
            std::string& out) {
    // A byte sequence the encoding lacks is passed over a code unit at a
    // time: a byte, or UTF-16's and UTF-32's units.
    const std::size_t unit = from.starts_with("UTF-32") ? 4 : from.starts_with("UTF-16") ? 2 : 1;
    const bool windows_1252 = from == "WINDOWS-1252";
    out.resize(std::min(max_bytes, in.size() + in.size() / 2 + 16));
    char* src = const_cast<char*>(in.data()); // iconv's signature; it does not write there
    std::size_t src_left = in.size(), done = 0;
    while (true) {
        char* dst = out.data() + done;
        std::size_t dst_left = out.size() - done;
        const std::size_t r = iconv(cd, src_left ? &src : nullptr, &src_left, &dst, &dst_left);
        done = out.size() - dst_left;
        if (r != std::size_t(-1) && src_left == 0) break;
        // Room for the conversion to go on, or for a U+FFFD (3 bytes).
        if (errno == E2BIG || out.size() - done < 3) {
            if (out.size() >= max_bytes) return false;
            out.resize(std::min(max_bytes, out.size() * 2));
            continue;
        }
        if (errno != EILSEQ && errno != EINVAL) return false;
        const unsigned char byte = static_cast<unsigned char>(*src);
        if (windows_1252) { // the C1 control of the same number (Encoding Standard, index)
            out[done++] = char(0xC2), out[done++] = char(byte);
        } else {
            for (const unsigned char b : {0xEF, 0xBF, 0xBD}) out[done++] = char(b);
        }
        const std::size_t skip = std::min(unit, src_left);
        src += skip, src_left -= skip;
        if (src_left == 0) break;
    }
    out.resize(done);
    return true;
}

} // namespace

DecodedDocument decode_document(std::string_view doc, std::size_t max_bytes) {
    DecodedDocument d;
    std::size_t skip = 0;
    std::string from = wide_encoding(doc, skip), label = from;
    if (from.empty()) {
        const Span at = declared_label(doc);
        if (at.pos == std::string_view::npos) return d; // UTF-8 (XML 1.0, 4.3.3)
        label = std::string(doc.substr(at.pos, at.len));
        from = decoder_for(label);
        // Bytes below 0x80 and no ISO 2022 escape: the same in every
        // ASCII-compatible encoding.
        const bool plain = std::none_of(doc.begin(), doc.end(), [](char c) {
            return static_cast<unsigned char>(c) >= 0x80 || c == 0x1B;
        });
        if (from.empty() || plain) return d;
    }
    const iconv_t cd = iconv_open("UTF-8", from.c_str());
    if (cd == iconv_t(-1)) {
        d.warning = "encoding '" + label + "' is not known: the text is read as UTF-8";
        return d;
    }
    const bool ok = decode(cd, doc.substr(skip), from, max_bytes, d.text);
    iconv_close(cd);
    if (!ok) {
        d.text = std::string();
        d.error = "the text decoded from " + label + " is over " + std::to_string(max_bytes) +
                  " bytes (the limit)";
        return d;
    }
    if (const Span at = declared_label(d.text); at.pos != std::string_view::npos)
        d.text.replace(at.pos, at.len, "UTF-8");
    d.changed = true;
    return d;
}

} // namespace casteljau
