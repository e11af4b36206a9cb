// The SVG reader: an SVG file (the subset of DESIGN.md) -> Scene.
//
// Errors are handled as SVG 2 and CSS specify, as browsers, resvg and
// librsvg do: an invalid attribute or property value is ignored (the
// property keeps its inherited or initial value: CSS Syntax 3; SVG 2,
// 6.9 "Presentation attributes"); path data and point lists are drawn up to
// their first error (SVG 2, 9.5.4; SVG 1.1 F.2); an element whose required
// value is in error (a negative width or radius) is not drawn; a broken
// reference falls back as the property says. Each such problem is one
// warning, located (file, line, element). Unknown elements and attributes
// are ignored; known elements this reader does not draw yet are skipped
// with a warning. With `strict`, the first problem is an error instead.
//
// Only a file that cannot be drawn at all is an error: not well-formed XML,
// a root that is not <svg>, an unusable size, or a limit exceeded. A
// DOCTYPE's internal entities are expanded within a limit (an expansion bomb
// is an error), an external entity is never read (svg/xml_entities.h). The
// only other files read are those an <image>, a <use>, an xml-stylesheet link
// or an @import names, from the SVG's folder or SvgOptions::resources_dir,
// never from the network (svg/resource_url.h).
//
// Limits (SvgOptions): file size, element count, nesting depth, attribute
// length and document size are checked before the work they bound.
#pragma once

#include "casteljau/render/output_size.h"
#include "casteljau/scene/scene.h"
#include "casteljau/text/font_database.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

/// What a document and the SVG images it draws have read, counted together
/// against SvgOptions::max_images and max_image_pixels_total.
struct ImageBudget {
    std::size_t images = 0;      ///< raster and SVG images read, and files \<use\> draws from
    std::size_t pixels = 0;      ///< raster pixels decoded
    std::size_t file_bytes = 0;  ///< of the files \<use\> draws from (max_file_bytes in all)
    std::size_t sheets = 0;      ///< style sheet files read (kMaxStyleSheetFiles)
    std::size_t sheet_bytes = 0; ///< their text (max_attribute_bytes in all)
};

/// Style sheet files one document reads, its xml-stylesheet links and
/// every \@import together (each read as often as it is imported), those of
/// its SVG images and of the files its \<use\>s draw from included; their
/// text is at most SvgOptions::max_attribute_bytes in all.
inline constexpr std::size_t kMaxStyleSheetFiles = 256;
/// How deep \@import rules nest (a sheet importing a sheet importing ...).
inline constexpr int kMaxStyleSheetNesting = 16;

/// Limits and options of the SVG reader.
struct SvgOptions {
    std::size_t max_file_bytes = std::size_t(256) << 20; ///< 256 MiB
    std::size_t max_elements = 1'000'000;
    int max_depth = 256; ///< element nesting
    /// Any one attribute: 32 MiB holds a million path segments ("L1234.5
    /// 678.9" is 14 bytes, an absolute cubic about 40).
    std::size_t max_attribute_bytes = std::size_t(32) << 20;
    /// What references to the DOCTYPE's entities add to the text, in all
    /// (svg/xml_entities.h): past it, an entity bomb is refused.
    std::size_t max_entity_bytes = std::size_t(16) << 20;
    double max_size = 16384; ///< document width and height, px
    /// The user's languages, for systemLanguage (conditional.h).
    std::vector<std::string> languages{"en"};
    /// The color scheme that \@media (prefers-color-scheme) matches in style
    /// sheets (svg/media_query.h): light, or dark when set.
    bool dark = false;
    /// The size the picture will be drawn at, as the front end asks for it
    /// (render/output_size.h): what \@media width, height, aspect-ratio and
    /// orientation are answered for. None given: the document's own size.
    SizeRequest media_size;
    /// The first problem in the input is an error (no image), instead of a
    /// warning and the spec's recovery.
    bool strict = false;
    /// Where the files an \<image\> or \<use\> names may come from, besides the SVG's
    /// own folder and below (svg/resource_url.h); "" for none. Images are
    /// never fetched from the network.
    std::string resources_dir;
    /// The SVG's folder, for relative hrefs: read_svg_file sets it from the
    /// path; parse_svg takes the current directory when it is "".
    std::string base_dir;
    /// An \<image\>'s pixels (width x height as its file declares them; 16
    /// bytes each once decoded, so 2^25 pixels are 512 MiB, and a third
    /// more once drawn smaller than half its size: its levels,
    /// paint/image_levels.h); a larger image is not drawn, with a warning.
    std::size_t max_image_pixels = std::size_t(1) << 25;
    /// SVG files drawn by \<image\> inside SVG files drawn by \<image\>, at
    /// most; and files a \<use\> draws from, inside such files
    /// (svg/external_use.cpp), as deep.
    int max_image_nesting = 8;
    /// Images and files a \<use\> draws from, read for a document, those of
    /// its SVG images included (a file that draws itself under many names is
    /// read this often at most), and the raster pixels they decode, together
    /// (1 GiB of float pixels).
    std::size_t max_images = 1000;
    std::size_t max_image_pixels_total = std::size_t(1) << 26;
    /// The count against those, shared with the readers of the SVG images a
    /// document draws; the reader makes one when it is null.
    std::shared_ptr<ImageBudget> image_budget;
    /// How deep this document is as an SVG image in SVG images: 0 for the
    /// document read, set by the reader for the images it reads.
    int image_depth = 0;
    /// Where text finds its fonts; null for FontDatabase::system() (the
    /// system's fonts, FONTCONFIG_FILE honoured, plus the CLI's --font-dir).
    FontDatabase* fonts = nullptr;
    /// Characters of text in a document, at most (a glyph's outline is
    /// about 2 KiB once read, so 1e5 of them are about 200 MiB); the text
    /// past the limit is not drawn, with a warning.
    std::size_t max_text_characters = 100'000;
};

/// A located message about the input.
struct SvgDiagnostic {
    std::string file;
    int line = 0;        ///< 1-based line of the element
    std::string element; ///< its name, without brackets
    std::string message; ///< what is wrong, and what was done about it
    /// "file:line: <element>: message", the form every message takes.
    std::string text() const;
};

/// A read SVG document: the scene, or a located error.
struct SvgResult {
    std::optional<Scene> scene;          ///< empty on error
    std::string error;                   ///< "file:line: <element>: what"
    bool io_error = false;               ///< the file could not be read (not its content)
    std::vector<SvgDiagnostic> warnings; ///< the problems recovered from, in document order
};

SvgResult read_svg_file(const std::string& path, const SvgOptions& options = {});
SvgResult parse_svg(std::string_view text, const std::string& name, const SvgOptions& options = {});

} // namespace casteljau
