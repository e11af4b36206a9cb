// A document's character encoding (XML 1.0, 4.3.3 and appendix F): the text
// the reader parses is UTF-8, whatever the file is in. pugixml reads UTF-8
// and, by their byte order marks, UTF-16 and UTF-32, and an ISO-8859-1
// declaration; but old files declare what their editor wrote them in
// (windows-1251, Shift_JIS, GBK, EUC-KR, ...), which browsers and librsvg
// decode and pugixml read as broken UTF-8 (a box for every letter). So the
// text is decoded first, with iconv (glibc's, the C library's own):
//
// - A byte order mark, or UTF-16 or UTF-32 without one (the first character
//   '<' in two or four bytes), gives the encoding, as appendix F says.
// - Otherwise the XML declaration's encoding, its label mapped as browsers
//   map it (the WHATWG Encoding Standard's labels: ISO-8859-1 and US-ASCII
//   are read as windows-1252, Shift_JIS as windows-31j, GB2312 as GBK, that
//   is GB18030, EUC-KR as windows-949, UTF-16 on a text that is not as
//   UTF-8), where it is not UTF-8. A document with no byte above 0x7F reads
//   the same in any of these and is left as it is.
// - A byte sequence the encoding does not have becomes U+FFFD, as browsers
//   decode it (windows-1252's five unassigned bytes, the C1 controls they
//   are in the Encoding Standard).
// - The declaration of the text decoded says UTF-8, so that pugixml reads
//   it so; it keeps its lines, so every line keeps its number (a warning's
//   line is the file's).
// A label the standard does not have is a warning, and the text is read as
// UTF-8, as it was before: the file does not choose among the C library's
// converters.
#pragma once

#include <string>
#include <string_view>

namespace casteljau {

/// The outcome of decode_document.
struct DecodedDocument {
    /// Whether the text was decoded; when not, `text` is empty and the
    /// document is read as it is.
    bool changed = false;
    std::string text;    ///< the document in UTF-8, its declaration saying so
    std::string warning; ///< "" or an encoding not known (the text is read as it is)
};

/// The document `doc` decoded to UTF-8 (top of the file): at most 3 bytes
/// a byte of `doc`.
DecodedDocument decode_document(std::string_view doc);

} // namespace casteljau
