// @font-face (CSS Fonts 4, 4): the fonts a document brings, as browsers
// draw them, where librsvg and resvg use only the system's.
//
// A rule needs a font-family and a src (4.1, 4.3); without either, or with
// an invalid one, it is ignored. src is a list of sources tried in order
// until one loads: url(), a data: URL decoded in memory or a file resolved
// as an <image>'s href is (svg/resource_url.h: no network, files only from
// the SVG's folder or the resources directory), with an optional format()
// hint (a source whose hint names a format FreeType does not read, "svg" or
// "embedded-opentype", is passed over unread); local() is passed over (it
// names an installed font, which the family list reaches anyway).
// font-weight is a weight or a range, font-style normal, italic or oblique
// (an angle after it is ignored); other descriptors are ignored.
// The loaded faces go to a FontDatabase layer of the document's own
// (FontDatabase::layer), which matches them before the system's fonts.
#pragma once

#include "casteljau/svg/css.h"
#include "casteljau/text/font_database.h"

#include <optional>
#include <string>
#include <vector>

namespace casteljau {

/// One src entry of an \@font-face rule.
struct FontFaceSource {
    std::string url;    ///< url()'s text, unquoted; empty for local()
    std::string format; ///< format()'s hint, lowercased; empty when none
};

/// An \@font-face rule, read: what it is for and where its font comes from.
struct FontFaceRule {
    FontFaceDescriptors descriptors;     ///< family, weight range, style
    std::vector<FontFaceSource> sources; ///< the url() sources, in order
};

/// Fonts a document may load through \@font-face, at most (a bound on the
/// fonts parsed per document; the rest are ignored with a warning).
inline constexpr int kMaxFontFaces = 64;
/// Bytes of a font file an \@font-face may load, at most (the largest fonts
/// shipped, CJK collections, are some 30 MB).
inline constexpr std::size_t kMaxFontFileBytes = std::size_t(64) << 20;

/// Reads a rule's descriptors; nullopt, with `error` saying why, when it is
/// to be ignored (no valid font-family or src).
std::optional<FontFaceRule> parse_font_face(const std::vector<CssDeclaration>& descriptors,
                                            std::string& error);

/// Whether a format() hint names a format FreeType reads: truetype,
/// opentype, woff, woff2, collection (and their -variations forms).
bool readable_font_format(std::string_view format);

} // namespace casteljau
