// Validation and loading shared by the subcommands, so that every command
// reports the same things the same way.
#pragma once

#include "casteljau/flatten/flatten.h"
#include "casteljau/scene/scene.h"
#include "casteljau/svg/reader.h"

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

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

// --strict, --languages (and the old --partial-path-data, now what is done
// anyway), into `o`.
void add_svg_options(CLI::App* cmd, SvgOptions& o);

// Reads an SVG file and prints its warnings. On failure prints the located
// error, sets `status` (2 bad input, 1 unreadable file) and returns nothing.
std::optional<Scene> load_svg(const std::string& path, const SvgOptions& options, int& status);

} // namespace casteljau::cli
