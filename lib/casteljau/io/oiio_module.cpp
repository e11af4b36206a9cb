#include "casteljau/io/detail/oiio_module.h"

#include "casteljau/io/image_read.h"

#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <system_error>
#include <vector>

namespace casteljau::detail {

namespace fs = std::filesystem;

namespace {

// Set by lib/CMakeLists.txt: the module's file name, the build tree's
// folder for it, the install's, and the library folder relative to a prefix.
constexpr const char* kName = CASTELJAU_OIIO_MODULE_NAME;
constexpr const char* kBuildDir = CASTELJAU_OIIO_BUILD_DIR;
constexpr const char* kInstallDir = CASTELJAU_OIIO_INSTALL_DIR;
constexpr const char* kLibDir = CASTELJAU_INSTALL_LIBDIR;
// Levels above a binary's folder where a prefix may be: PREFIX/bin is one,
// PREFIX/lib/python3/dist-packages/casteljau four.
constexpr int kPrefixLevels = 4;

void add(std::vector<fs::path>& paths, const fs::path& p) {
    for (const fs::path& q : paths)
        if (q == p) return;
    paths.push_back(p);
}

/// The module next to a binary in `dir`, and where an install puts it
/// relative to the prefixes above `dir`.
void add_near(std::vector<fs::path>& paths, fs::path dir) {
    std::error_code ec;
    dir = fs::absolute(dir, ec).lexically_normal();
    if (ec || dir.empty()) return;
    add(paths, dir / kName);
    for (int up = 0; up <= kPrefixLevels; ++up, dir = dir.parent_path())
        add(paths, dir / kLibDir / "casteljau" / kName);
}

std::vector<fs::path> candidates() {
    std::vector<fs::path> paths;
    Dl_info info{};
    if (dladdr(reinterpret_cast<const void*>(&oiio_module), &info) && info.dli_fname &&
        *info.dli_fname)
        add_near(paths, fs::path(info.dli_fname).parent_path());
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) add_near(paths, exe.parent_path());
    add(paths, fs::path(kBuildDir) / kName);
    add(paths, fs::path(kInstallDir) / kName);
    return paths;
}

/// Loads the module at `path`: its codec, or null with `why` set.
const OiioCodec* load(const fs::path& path, std::string& why) {
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        // dlerror names the file when it is the module itself at fault, not
        // when a library it needs is missing.
        const char* e = dlerror();
        why = e ? e : "cannot be loaded";
        if (!why.starts_with(path.string())) why = path.string() + ": " + why;
        return nullptr;
    }
    using Entry = const OiioCodec* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, kOiioEntry));
    const OiioCodec* codec = entry ? entry() : nullptr;
    if (!codec) {
        why = path.string() + ": not a module of this version (no " + kOiioEntry + ")";
        dlclose(handle);
    }
    // Otherwise the module stays loaded for the process's life.
    return codec;
}

/// The first candidate that loads. A candidate found but unusable (a
/// missing dependency, another version) is passed over and reported if
/// none loads.
OiioModule find() {
    OiioModule m;
    std::vector<fs::path> paths;
    const char* chosen = std::getenv("CASTELJAU_OIIO_MODULE");
    if (chosen && *chosen) // absolute: dlopen would search the library path for a bare name
        paths.emplace_back(fs::absolute(chosen));
    else
        paths = candidates();
    std::string searched, unusable;
    for (const fs::path& p : paths) {
        searched += (searched.empty() ? "" : ", ") + p.string();
        std::error_code ec;
        if (!fs::is_regular_file(p, ec)) continue;
        std::string why;
        if ((m.codec = load(p, why))) return m;
        unusable += (unusable.empty() ? "" : "; ") + why;
    }
    const std::string named = chosen && *chosen ? ", as CASTELJAU_OIIO_MODULE says" : "";
    m.error = unusable.empty() ? std::string("module ") + kName + " not found (searched " +
                                     searched + named + ")"
                               : std::string("module ") + kName + " cannot be loaded: " + unusable +
                                     (named.empty() ? "" : " (" + named.substr(2) + ")");
    return m;
}

} // namespace

const OiioModule& oiio_module() {
    static const OiioModule module = find(); // thread-safe, once (C++11 6.7)
    return module;
}

std::string oiio_missing(const std::string& doing) {
    return doing + " needs OpenImageIO: " + oiio_module().error;
}

} // namespace casteljau::detail

namespace casteljau {

bool openimageio_available(std::string* why) {
    const detail::OiioModule& m = detail::oiio_module();
    if (why) *why = m.error;
    return m.codec != nullptr;
}

} // namespace casteljau
