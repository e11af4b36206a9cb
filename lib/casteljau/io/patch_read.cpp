#include "casteljau/io/patch_read.h"

#include "casteljau/io/detail/patch_formats.h"
#include "casteljau/io/text_file.h"

#include <filesystem>

namespace casteljau {

PatchFile parse_patches(std::string_view text, PatchFormat format, const std::string& name,
                        const PatchLimits& limits) {
    PatchFile out;
    try {
        switch (format) {
        case PatchFormat::Bpt:
            out.model = detail::parse_bpt(text, limits);
            break;
        case PatchFormat::QuakeMap:
            out.model = detail::parse_quake_map(text, limits);
            break;
        case PatchFormat::Json:
            out.model = detail::parse_patch_json(text, limits, out.camera);
            break;
        }
    } catch (const detail::ReadError& e) {
        out.model.reset();
        out.camera.reset();
        out.error = name + ":" + std::to_string(e.line) + ": " + e.what;
    }
    return out;
}

PatchFile read_patch_file(const std::string& path, const PatchLimits& limits) {
    namespace fs = std::filesystem;
    const std::string ext = fs::path(path).extension().string();
    PatchFile out;
    PatchFormat format;
    if (ext == ".bpt")
        format = PatchFormat::Bpt;
    else if (ext == ".map")
        format = PatchFormat::QuakeMap;
    else if (ext == ".json")
        format = PatchFormat::Json;
    else {
        out.error = path + ": unknown patch format '" + ext + "' (expected .bpt, .map or .json)";
        return out;
    }
    const TextFile file = read_text_file(path, limits.max_file_bytes);
    if (!file.error.empty()) {
        out.error = file.error;
        out.io_error = file.io_error;
        return out;
    }
    return parse_patches(file.text, format, path, limits);
}

} // namespace casteljau
