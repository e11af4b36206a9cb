#include "casteljau/svg/xml_encoding.h"

#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/detail/pseudo_attributes.h"

#include <algorithm>
#include <cerrno>
#include <iconv.h>
#include <initializer_list>

namespace casteljau {

namespace {

// Where the XML declaration ends (after its "?>"), or 0 when the text has
// none: it is the text's very start (XML 1.0, 2.8).
std::size_t declaration_end(std::string_view text) {
    if (!text.starts_with("<?xml") || text.size() < 6 || !svg_detail::is_xml_space(text[5]))
        return 0;
    const std::size_t close = text.find("?>");
    return close == std::string_view::npos ? 0 : close + 2;
}

// The declaration's encoding label (4.3.3), "" when it has none.
std::string declared_label(std::string_view text) {
    const std::size_t end = declaration_end(text);
    if (end == 0) return {};
    const auto a = svg_detail::pseudo_attributes(text.substr(5, end - 7));
    const auto it = a.find("encoding");
    return it == a.end() ? std::string() : it->second;
}

// The Encoding Standard's labels (WHATWG, 4.2) and the decoder each names,
// as iconv names it ("" for UTF-8). A label not here is not decoded, what
// iconv may know aside: the file does not choose among the C library's
// converters. UTF-16's labels on a text that is not UTF-16 (no zero bytes,
// checked first) read as UTF-8, as the standard's decoding does. GBK is
// read as GB18030, which the standard's GBK decoder is.
struct Decoder {
    const char* name;
    std::initializer_list<std::string_view> labels;
};
const Decoder kDecoders[] = {
    {"",
     {"unicode-1-1-utf-8", "unicode11utf8", "unicode20utf8", "utf-8", "utf8", "x-unicode20utf8",
      "csunicode", "iso-10646-ucs-2", "ucs-2", "unicode", "unicodefeff", "utf-16", "utf-16le",
      "unicodefffe", "utf-16be"}},
    {"IBM866", {"866", "cp866", "csibm866", "ibm866"}},
    {"ISO-8859-2",
     {"csisolatin2", "iso-8859-2", "iso-ir-101", "iso8859-2", "iso88592", "iso_8859-2",
      "iso_8859-2:1987", "l2", "latin2"}},
    {"ISO-8859-3",
     {"csisolatin3", "iso-8859-3", "iso-ir-109", "iso8859-3", "iso88593", "iso_8859-3",
      "iso_8859-3:1988", "l3", "latin3"}},
    {"ISO-8859-4",
     {"csisolatin4", "iso-8859-4", "iso-ir-110", "iso8859-4", "iso88594", "iso_8859-4",
      "iso_8859-4:1988", "l4", "latin4"}},
    {"ISO-8859-5",
     {"csisolatincyrillic", "cyrillic", "iso-8859-5", "iso-ir-144", "iso8859-5", "iso88595",
      "iso_8859-5", "iso_8859-5:1988"}},
    {"ISO-8859-6",
     {"arabic", "asmo-708", "csiso88596e", "csiso88596i", "csisolatinarabic", "ecma-114",
      "iso-8859-6", "iso-8859-6-e", "iso-8859-6-i", "iso-ir-127", "iso8859-6", "iso88596",
      "iso_8859-6", "iso_8859-6:1987"}},
    {"ISO-8859-7",
     {"csisolatingreek", "ecma-118", "elot_928", "greek", "greek8", "iso-8859-7", "iso-ir-126",
      "iso8859-7", "iso88597", "iso_8859-7", "iso_8859-7:1987", "sun_eu_greek"}},
    {"ISO-8859-8",
     {"csiso88598e", "csisolatinhebrew", "hebrew", "iso-8859-8", "iso-8859-8-e", "iso-ir-138",
      "iso8859-8", "iso88598", "iso_8859-8", "iso_8859-8:1988", "visual", "csiso88598i",
      "iso-8859-8-i", "logical"}},
    {"ISO-8859-10",
     {"csisolatin6", "iso-8859-10", "iso-ir-157", "iso8859-10", "iso885910", "l6", "latin6"}},
    {"ISO-8859-13", {"iso-8859-13", "iso8859-13", "iso885913"}},
    {"ISO-8859-14", {"iso-8859-14", "iso8859-14", "iso885914"}},
    {"ISO-8859-15", {"csisolatin9", "iso-8859-15", "iso8859-15", "iso885915", "iso_8859-15", "l9"}},
    {"ISO-8859-16", {"iso-8859-16"}},
    {"KOI8-R", {"cskoi8r", "koi", "koi8", "koi8-r", "koi8_r"}},
    {"KOI8-U", {"koi8-ru", "koi8-u"}},
    {"MACINTOSH", {"csmacintosh", "mac", "macintosh", "x-mac-roman"}},
    {"WINDOWS-874",
     {"dos-874", "iso-8859-11", "iso8859-11", "iso885911", "tis-620", "windows-874"}},
    {"WINDOWS-1250", {"cp1250", "windows-1250", "x-cp1250"}},
    {"WINDOWS-1251", {"cp1251", "windows-1251", "x-cp1251"}},
    {"WINDOWS-1252",
     {"ansi_x3.4-1968", "ascii", "cp1252", "cp819", "csisolatin1", "ibm819", "iso-8859-1",
      "iso-ir-100", "iso8859-1", "iso88591", "iso_8859-1", "iso_8859-1:1987", "l1", "latin1",
      "us-ascii", "windows-1252", "x-cp1252"}},
    {"WINDOWS-1253", {"cp1253", "windows-1253", "x-cp1253"}},
    {"WINDOWS-1254",
     {"cp1254", "csisolatin5", "iso-8859-9", "iso-ir-148", "iso8859-9", "iso88599", "iso_8859-9",
      "iso_8859-9:1989", "l5", "latin5", "windows-1254", "x-cp1254"}},
    {"WINDOWS-1255", {"cp1255", "windows-1255", "x-cp1255"}},
    {"WINDOWS-1256", {"cp1256", "windows-1256", "x-cp1256"}},
    {"WINDOWS-1257", {"cp1257", "windows-1257", "x-cp1257"}},
    {"WINDOWS-1258", {"cp1258", "windows-1258", "x-cp1258"}},
    {"MAC-CYRILLIC", {"x-mac-cyrillic", "x-mac-ukrainian"}},
    {"GB18030",
     {"chinese", "csgb2312", "csiso58gb231280", "gb2312", "gb_2312", "gb_2312-80", "gbk",
      "iso-ir-58", "x-gbk", "gb18030"}},
    {"BIG5-HKSCS", {"big5", "big5-hkscs", "cn-big5", "csbig5", "x-x-big5"}},
    {"EUC-JP", {"cseucpkdfmtjapanese", "euc-jp", "x-euc-jp"}},
    {"ISO-2022-JP", {"csiso2022jp", "iso-2022-jp"}},
    {"CP932",
     {"csshiftjis", "ms932", "ms_kanji", "shift-jis", "shift_jis", "sjis", "windows-31j",
      "x-sjis"}},
    {"CP949",
     {"cseuckr", "csksc56011987", "euc-kr", "iso-ir-149", "korean", "ks_c_5601-1987",
      "ks_c_5601-1989", "ksc5601", "ksc_5601", "windows-949"}},
};

// The decoder of `label` (ASCII case aside), or null when the standard has none.
const char* decoder_for(std::string_view label) {
    std::string lower(label);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return char(c >= 'A' && c <= 'Z' ? c + 32 : c); });
    for (const Decoder& d : kDecoders)
        if (std::find(d.labels.begin(), d.labels.end(), lower) != d.labels.end()) return d.name;
    return nullptr;
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
    // '<' and any other character, as pugixml finds them (a document may
    // start <svg or <!DOCTYPE).
    if (t.size() >= 4 && starts({0x00, 0x3C}) && t[2] == 0 && t[3] != 0) return "UTF-16BE";
    if (t.size() >= 4 && starts({0x3C, 0x00}) && t[2] != 0 && t[3] == 0) return "UTF-16LE";
    return "";
}

// `in` decoded from `from` into `out`. It grows to at most 3 bytes an input
// byte: a U+FFFD for a byte, or a BMP character for a single-byte one; wider
// input (two bytes and more) gives at most as many bytes in UTF-8.
void decode(iconv_t cd, std::string_view in, const std::string& from, std::string& out) {
    // A byte sequence the encoding lacks is passed over a code unit at a
    // time: a byte, or UTF-16's and UTF-32's units.
    const std::size_t unit = from.starts_with("UTF-32") ? 4 : from.starts_with("UTF-16") ? 2 : 1;
    const bool windows_1252 = from == "WINDOWS-1252", gb18030 = from == "GB18030";
    out.resize(in.size() + in.size() / 2 + 16);
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
            out.resize(out.size() * 2);
            continue;
        }
        // EILSEQ, or EINVAL (a sequence cut off at the end): passed over.
        const unsigned char byte = static_cast<unsigned char>(*src);
        if (windows_1252) { // the C1 control of the same number (Encoding Standard, index)
            out[done++] = char(0xC2), out[done++] = char(byte);
        } else if (gb18030 && byte == 0x80) { // the standard's GBK decoder: U+20AC, the euro
            for (const unsigned char b : {0xE2, 0x82, 0xAC}) out[done++] = char(b);
        } else {
            for (const unsigned char b : {0xEF, 0xBF, 0xBD}) out[done++] = char(b);
        }
        const std::size_t skip = std::min(unit, src_left);
        src += skip, src_left -= skip;
        if (src_left == 0) break;
    }
    out.resize(done);
}

} // namespace

DecodedDocument decode_document(std::string_view doc) {
    DecodedDocument d;
    std::size_t skip = 0;
    std::string from = wide_encoding(doc, skip), label = from;
    if (from.empty()) {
        label = declared_label(doc);
        if (label.empty()) return d; // UTF-8 (XML 1.0, 4.3.3)
        // Bytes below 0x80 and no ISO 2022 escape: the same in every
        // ASCII-compatible encoding.
        const bool plain = std::none_of(doc.begin(), doc.end(), [](char c) {
            return static_cast<unsigned char>(c) >= 0x80 || c == 0x1B;
        });
        const char* decoder = decoder_for(label);
        if (!decoder && !plain)
            d.warning = "encoding '" + label + "' is not known: the text is read as UTF-8";
        if (!decoder || !*decoder || plain) return d;
        from = decoder;
    }
    const iconv_t cd = iconv_open("UTF-8", from.c_str());
    if (cd == iconv_t(-1)) { // a C library without the converter
        d.warning = "encoding '" + label + "' cannot be decoded here: the text is read as UTF-8";
        return d;
    }
    decode(cd, doc.substr(skip), from, d.text);
    iconv_close(cd);
    // The declaration says UTF-8 now, on as many lines as it took.
    if (const std::size_t end = declaration_end(d.text)) {
        const auto lines = std::count(d.text.begin(), d.text.begin() + std::ptrdiff_t(end), '\n');
        d.text.replace(0, end,
                       "<?xml version=\"1.0\" encoding=\"UTF-8\"?>" +
                           std::string(std::size_t(lines), '\n'));
    }
    d.changed = true;
    return d;
}

} // namespace casteljau
