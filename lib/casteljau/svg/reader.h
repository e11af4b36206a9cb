// The SVG reader: an SVG file (the subset of DESIGN.md) -> Scene.
//
// Errors name the file, the line and the element ("in.svg:12: <rect>:
// attribute width: 'abc' is not a length"); XML errors come from pugixml with
// their offset turned into a line. Malformed values are errors, bad path data
// and point lists included (DESIGN.md: "anything malformed is an error");
// with `partial_path_data` they follow SVG 1.1 appendix F.2 instead, as
// browsers do: the path is drawn up to the error, with a warning.
// Unsupported elements are skipped with a warning each.
// No DTD is processed, so no entity is ever expanded and no external
// reference is ever followed; a DOCTYPE that declares entities (an expansion
// bomb, an external entity) is an error, a plain one is ignored.
//
// Limits (SvgOptions): file size, element count, nesting depth, attribute
// length and document size are checked before the work they bound.
#pragma once

#include "casteljau/scene/scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

/// Limits and options of the SVG reader.
struct SvgOptions {
    std::size_t max_file_bytes = std::size_t(256) << 20; ///< 256 MiB
    std::size_t max_elements = 1'000'000;
    int max_depth = 256; ///< element nesting
    /// Any one attribute: 32 MiB holds a million path segments ("L1234.5
    /// 678.9" is 14 bytes, an absolute cubic about 40).
    std::size_t max_attribute_bytes = std::size_t(32) << 20;
    double max_size = 16384;        ///< document width and height, px
    bool partial_path_data = false; ///< draw bad path data up to the error (F.2), warning
};

/// A read SVG document: the scene, or a located error.
struct SvgResult {
    std::optional<Scene> scene; ///< empty on error
    std::string error;          ///< "file:line: <element>: what"
    bool io_error = false;      ///< the file could not be read (not its content)
    std::vector<std::string> warnings;
};

SvgResult read_svg_file(const std::string& path, const SvgOptions& options = {});
SvgResult parse_svg(std::string_view text, const std::string& name, const SvgOptions& options = {});

} // namespace casteljau
