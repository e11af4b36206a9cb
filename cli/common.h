// Validation and loading shared by the subcommands, so that every command
// reports the same things the same way.
#pragma once

#include "casteljau/flatten/flatten.h"
#include "casteljau/scene/scene.h"
#include "casteljau/svg/reader.h"

#include <optional>
#include <string>
#include <string_view>

namespace CLI {
class App; // <CLI/CLI.hpp>: only the files that add options compile it (5 s each)
}

namespace casteljau::cli {

// Tolerances are device pixels in [kMinTolerance, 1]: smaller ones ask for
// segment counts no raster can use (and, on large coordinates, below the
// doubles' own resolution); above one pixel is not what the product promises.
inline constexpr double kMinTolerance = 1e-4;

// Output image limits: each side at most 16384 px, and at most 2^26 pixels in
// all (64 Mpx: a 1 GiB float canvas), checked before anything is allocated.
inline constexpr int kMaxSide = 16384;
inline constexpr double kMaxPixels = double(1 << 26);

// --tolerance, the same in every command.
void add_tolerance_option(CLI::App* cmd, double& tolerance);
// --tolerance, --flatten adaptive|uniform|halving and --segments N, into `o`.
void add_flatten_options(CLI::App* cmd, FlattenOptions& o);

// True when valid; otherwise prints "casteljau COMMAND: --tolerance X: ..." and
// returns false (the caller exits with status 2).
bool check_tolerance(const char* command, double tolerance);

// --strict, --languages, --color-scheme, --resources-dir and the fonts'
// options (and the old --partial-path-data, now what is done anyway), into `o`.
void add_svg_options(CLI::App* cmd, SvgOptions& o);

// What a command has to say about one input, kept to be printed in one
// piece: the messages of files rendered at the same time never interleave.
struct Messages {
    std::string text;  ///< "warning: ...\n" and "error: ...\n" lines, in order
    std::string error; ///< the first error, without its "error: "
    int warnings = 0;

    void warn(std::string_view what);
    void fail(std::string_view what);
    /// Writes `text` to stderr in one call (stdio locks the stream for it).
    void print() const;
};

// Reads an SVG file; its warnings go to `log`. On failure logs the located
// error, sets `status` (2 bad input, 1 unreadable file) and returns nothing.
std::optional<Scene> load_svg(const std::string& path, const SvgOptions& options, int& status,
                              Messages& log);

} // namespace casteljau::cli
