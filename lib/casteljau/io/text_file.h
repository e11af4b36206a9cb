// Reading a whole text file under a size limit: the one way every reader
// (SVG, patch files) loads its input. The size is checked before anything is
// allocated, so an oversized file costs nothing.
#pragma once

#include <cstddef>
#include <string>

namespace casteljau {

/// A whole text file read into memory, or why it could not be.
struct TextFile {
    std::string text;
    std::string error;     ///< empty on success: "path: what"
    bool io_error = false; ///< could not be read (as opposed to: too large)
};

TextFile read_text_file(const std::string& path, std::size_t max_bytes);

} // namespace casteljau
