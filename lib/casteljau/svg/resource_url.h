// What the href of an <image> may refer to, and how it is resolved: a data:
// URL (RFC 2397), decoded in memory, or a file, under rules that keep an SVG
// from reading what its user did not offer: no network access ever, and
// files only from the SVG's folder and below, or below a resources
// directory the user names.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

/// The content of a data: URL.
struct DataUrl {
    std::string mime; ///< type/subtype, lowercase, without parameters; "text/plain" if none given
    std::vector<unsigned char> bytes; ///< the data, decoded
};

/// Decodes `data:[<mediatype>][;base64],<data>` (the scheme in any case).
/// nullopt with `error` empty when `url` is not a data: URL at all; nullopt
/// with `error` set when it is one but malformed (no comma, bad base64).
std::optional<DataUrl> parse_data_url(std::string_view url, std::string& error);

/// A file an href refers to, or why it may not be read.
struct ResourcePath {
    std::string path;  ///< canonical (symlinks resolved): the file to open
    std::string error; ///< empty on success
};

/// Resolves `href` (a relative or absolute path, or a file: URL; query and
/// fragment ignored, percent-escapes decoded) against `svg_dir`, the folder
/// of the SVG (the current directory when empty). The result must lie within
/// `root_dir` (svg_dir when empty: a file that another file names, a style
/// sheet or a sprite, resolves against its own folder but stays within the
/// SVG's), or within `resources_dir` when that is not empty, after symlinks
/// are resolved; any other scheme, or a host, is refused: no network access.
ResourcePath resolve_resource_path(std::string_view href, const std::string& svg_dir,
                                   const std::string& resources_dir,
                                   const std::string& root_dir = "");

} // namespace casteljau
