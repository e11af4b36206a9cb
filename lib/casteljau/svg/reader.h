// The SVG reader: an SVG file (the subset of DESIGN.md) -> Scene.
//
// Errors name the file, the line and the element ("in.svg:12: <rect>:
// attribute width: 'abc' is not a length"); XML errors come from pugixml with
// their offset turned into a line. Following SVG 1.1 appendix F.2, bad path
// data draws the path up to the error with a warning; every other malformed
// value is an error. Unsupported elements are skipped with a warning each.
// No DTD is processed, so no entity is ever expanded and no external
// reference is ever followed (pugixml without parse_doctype).
//
// Limits (SvgLimits): file size, element count, nesting depth and document
// size are checked before the work they bound.
#pragma once

#include "casteljau/scene/scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

struct SvgLimits {
    std::size_t max_file_bytes = std::size_t(256) << 20; // 256 MiB
    std::size_t max_elements = 1'000'000;
    int max_depth = 256;     // element nesting
    double max_size = 16384; // document width and height, px
};

struct SvgResult {
    std::optional<Scene> scene; // empty on error
    std::string error;          // "file:line: <element>: what"
    bool io_error = false;      // the file could not be read (not its content)
    std::vector<std::string> warnings;
};

SvgResult read_svg_file(const std::string& path, const SvgLimits& limits = {});
SvgResult parse_svg(std::string_view text, const std::string& name, const SvgLimits& limits = {});

} // namespace casteljau
