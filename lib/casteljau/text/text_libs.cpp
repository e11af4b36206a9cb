// Opening the text libraries on first use (see text/detail/text_libs.h).
#include "casteljau/text/detail/text_libs.h"

#include "casteljau/text/font.h"

#include <dlfcn.h>

namespace casteljau {

namespace {

// The sonames lib/CMakeLists.txt read off the libraries this build was
// configured with (their major versions: an ABI the headers match).
constexpr TextLibs::Sonames kBuildSonames = {CASTELJAU_SONAME_FREETYPE, CASTELJAU_SONAME_HARFBUZZ,
                                             CASTELJAU_SONAME_FONTCONFIG, CASTELJAU_SONAME_FRIBIDI};

// The loader's reason (it names the library, and the function if one is
// missing), or that `what` cannot be loaded.
std::string loader_error(const char* what) {
    const char* why = dlerror();
    return why ? why : std::string(what) + ": cannot be loaded";
}

// Sets `f` to the function `name` of `library`; false, with `error` set, when it is not there.
template <class F>
bool resolve(F& f, void* library, const char* name, std::string& error) {
    f = reinterpret_cast<F>(dlsym(library, name));
    if (!f) error = loader_error(name);
    return f != nullptr;
}

} // namespace

TextLibs TextLibs::load(const Sonames& sonames) {
    TextLibs libs;
    std::array<void*, kLibraries> handles{};
    for (std::size_t i = 0; i < handles.size(); ++i)
        if (!(handles[i] = dlopen(sonames[i], RTLD_NOW | RTLD_LOCAL))) {
            libs.error = loader_error(sonames[i]);
            return libs;
        }
#define CASTELJAU_TEXT_RESOLVE(library, function)                                                  \
    if (!resolve(libs.function, handles[library], #function, libs.error)) return libs;
    CASTELJAU_TEXT_FUNCTIONS(CASTELJAU_TEXT_RESOLVE)
#undef CASTELJAU_TEXT_RESOLVE
    return libs;
}

const TextLibs& text_libs() {
    static const TextLibs libs = TextLibs::load(kBuildSonames); // thread-safe, once (C++11 6.7)
    return libs;
}

const std::string& text_libraries_error() { return text_libs().error; }

} // namespace casteljau
