#include "common.h"

#include "casteljau/svg/reader.h"
#include "commands.h"

#include <cstdio>

namespace casteljau::cli {

bool check_tolerance(const char* command, double tolerance) {
    if (tolerance >= kMinTolerance && tolerance <= 1.0) return true;
    std::fprintf(stderr,
                 "casteljau %s: --tolerance %g: must be a number of device pixels in [%g, 1]\n",
                 command, tolerance, kMinTolerance);
    return false;
}

std::optional<Scene> load_svg(const std::string& path, int& status) {
    SvgResult doc = read_svg_file(path);
    for (const std::string& w : doc.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (!doc.scene) {
        std::fprintf(stderr, "error: %s\n", doc.error.c_str());
        status = doc.io_error ? kExitFailure : kExitBadInput;
    }
    return std::move(doc.scene);
}

} // namespace casteljau::cli
