// Finding and loading the OpenImageIO module (see oiio_codec.h), once, on
// first use, from any thread.
//
// Where it is looked for, in order (the first that loads wins):
// 1. the file CASTELJAU_OIIO_MODULE names, when that variable is set (then
//    nowhere else: a test or a packager states exactly which module);
// 2. next to the executable or shared object the library is linked into
//    (dladdr), and next to /proc/self/exe; and for each of those folders and
//    its four parents P, P/LIBDIR/casteljau, where an installed module is
//    relative to an installed program (PREFIX/bin) or Python package
//    (PREFIX/lib/python3/dist-packages/casteljau), whatever the prefix;
// 3. the build tree's output folder for the module;
// 4. the configured install location, CMAKE_INSTALL_FULL_LIBDIR/casteljau.
#pragma once

#include "casteljau/io/detail/oiio_codec.h"

#include <string>

namespace casteljau::detail {

/// The loaded module, or why there is none.
struct OiioModule {
    const OiioCodec* codec = nullptr; ///< null when the module could not be loaded
    /// "module libcasteljau_oiio.so not found (searched ...)", or the
    /// loader's reason for a module found but unusable.
    std::string error;
};

/// The module, loaded on the first call; later calls return the same result.
const OiioModule& oiio_module();

/// "DOING needs OpenImageIO: " followed by the module's error: the message
/// for an operation that could not get the module.
std::string oiio_missing(const std::string& doing);

} // namespace casteljau::detail
