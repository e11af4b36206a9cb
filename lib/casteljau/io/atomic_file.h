// The temporary-file-and-rename protocol shared by every writer in io/: the
// output is written to a hidden sibling of the destination (same folder, so
// the rename is atomic; same extension, so format-by-extension writers pick
// the same format) and renamed over the destination only once complete. A
// failed or interrupted write never damages an existing file.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace casteljau {

/// ".NAME.tmp-PID.EXT" next to `dest`.
std::filesystem::path temporary_sibling(const std::filesystem::path& dest);

/// Renames `tmp` over `dest` when `error` is empty, removes it otherwise, and
/// returns the error (the rename's own, if it fails).
std::string finish_temporary(const std::filesystem::path& tmp, const std::filesystem::path& dest,
                             std::string error);

/// Writes `bytes` to `dest` through a temporary sibling. Every write, the
/// flush to the disk (fsync) and the close are checked, since a full disk may
/// only show at the last two; returns "" or "DEST: what failed".
std::string write_file_atomic(const std::filesystem::path& dest, std::string_view bytes);

} // namespace casteljau
