#include "casteljau/io/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
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

std::string write_file_atomic(const fs::path& dest, std::string_view bytes) {
    std::error_code ec;
    if (fs::is_directory(dest, ec)) return dest.string() + ": is a folder, not a file";
    const fs::path tmp = temporary_sibling(dest);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) return dest.string() + ": cannot write: " + std::strerror(errno);
    std::string error;
    for (std::size_t done = 0; done < bytes.size() && error.empty();) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n > 0)
            done += std::size_t(n);
        else if (n < 0 && errno != EINTR)
            error = dest.string() + ": write failed: " + std::strerror(errno);
    }
    if (error.empty() && ::fsync(fd) != 0)
        error = dest.string() + ": write failed: " + std::strerror(errno);
    if (::close(fd) != 0 && error.empty())
        error = dest.string() + ": write failed: " + std::strerror(errno);
    return finish_temporary(tmp, dest, std::move(error));
}

} // namespace casteljau
