#include "casteljau/io/atomic_file.h"

#include <system_error>
#include <unistd.h>

namespace casteljau {

namespace fs = std::filesystem;

fs::path temporary_sibling(const fs::path& dest) {
    // Built by appending: GCC 12 warns falsely (-Wrestrict, PR 105329) on the
    // equivalent chain of operator+ with a leading literal.
    std::string name(".");
    name.append(dest.stem().string()).append(".tmp-").append(std::to_string(::getpid()));
    name.append(dest.extension().string());
    return dest.parent_path() / name;
}

std::string finish_temporary(const fs::path& tmp, const fs::path& dest, std::string error) {
    std::error_code ec;
    if (error.empty()) {
        fs::rename(tmp, dest, ec);
        if (ec)
            error = dest.string() + ": cannot move the finished file into place: " + ec.message();
    }
    if (!error.empty()) fs::remove(tmp, ec);
    return error;
}

} // namespace casteljau
