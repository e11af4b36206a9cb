// Reading surface patches: Utah teapot .bpt, Quake 3 .map, and the JSON scene.
//
// Formats (DESIGN.md, "Patch inputs"):
// * .bpt: the patch count, then per patch a line "m n" (degrees in u and v,
//   1..3) and (m+1)(n+1) points "x y z": n + 1 rows of m + 1 points, rows
//   along v. Texture coordinates are the patch's own (u, v).
// * .map: every patchDef2 block; "( W H 0 0 0 )" then W rows of H points
//   "( x y z s t )", W and H odd and >= 3: (W-1)/2 x (H-1)/2 biquadratic
//   patches sharing their edges. Everything outside patchDef2 is skipped.
// * .json: {"patches": [{"type": "bezier"|"bspline", "degree": [m, n],
//   "points": [[x, y, z], ...], "st": [[s, t], ...]}], "camera": {"eye": [..],
//   "target": [..], "up": [..], "fov": degrees}}. A bezier patch has
//   (m+1)(n+1) points in n + 1 rows (rows along v); a bspline grid has
//   "size": [rows, columns] (default [4, 4], each >= 4) and is cut into
//   overlapping 4 x 4 pieces. "st" is optional (default: the grid's own
//   parameters); "camera" is optional, and needs "eye" and "target".
//
// Errors are "file:line: what" (wrong counts, even or small grid sizes,
// non-numbers, NaN or infinity, truncation); limits are checked as read.
#pragma once

#include "casteljau/patch/patch_model.h"
#include "casteljau/render3d/camera.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace casteljau {

/// Limits on patch files (size, patch count, nesting), all checked with located errors.
struct PatchLimits {
    std::size_t max_file_bytes = std::size_t(256) << 20; ///< 256 MiB
    std::size_t max_patches = 1'000'000;
    int max_grid_side = 1025; ///< control points along one side of a .map or B-spline grid
};

enum class PatchFormat { Bpt, QuakeMap, Json };

/// A read patch file: the model and camera, or a located error.
struct PatchFile {
    std::optional<PatchModel> model; ///< empty on error
    std::optional<LookAt> camera;    ///< from a .json scene that has one
    std::string error;               ///< "file:line: what"
    bool io_error = false;           ///< the file could not be read (not its content)
};

/// The format follows the extension (.bpt, .map, .json); anything else is an error.
PatchFile read_patch_file(const std::string& path, const PatchLimits& limits = {});
PatchFile parse_patches(std::string_view text, PatchFormat format, const std::string& name,
                        const PatchLimits& limits = {});

} // namespace casteljau
