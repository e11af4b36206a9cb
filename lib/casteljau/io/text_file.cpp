#include "casteljau/io/text_file.h"

#include <filesystem>
#include <fstream>

namespace casteljau {

TextFile read_text_file(const std::string& path, std::size_t max_bytes) {
    TextFile f;
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) {
        f.error = path + ": cannot read: " + ec.message();
        f.io_error = true;
        return f;
    }
    if (size > max_bytes) {
        f.error = path + ": " + std::to_string(size) + " bytes exceed the limit of " +
                  std::to_string(max_bytes);
        return f;
    }
    std::ifstream in(path, std::ios::binary);
    f.text.assign(size, '\0');
    if (!in || !in.read(f.text.data(), std::streamsize(size))) {
        f.text.clear();
        f.error = path + ": cannot read the file";
        f.io_error = true;
    }
    return f;
}

} // namespace casteljau
