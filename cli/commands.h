// The subcommands of the `casteljau` tool. Each registers its options on the
// CLI11 app and returns the function that runs it; exit statuses follow the
// contract in DESIGN.md: 0 success, 2 bad usage or input, 1 other failure.
#pragma once

#include <functional>

namespace CLI {
class App; // <CLI/CLI.hpp>: only the files that add options compile it (5 s each)
}

namespace casteljau::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

using Command = std::function<int()>;

Command add_flatten_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_patch_command(CLI::App& app);

} // namespace casteljau::cli
