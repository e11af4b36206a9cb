#include "casteljau/io/image_write.h"

#include "casteljau/io/atomic_file.h"

#include <OpenImageIO/imageio.h>
#include <filesystem>
#include <memory>
#include <system_error>
#include <utility>

namespace casteljau {

namespace fs = std::filesystem;

namespace {

bool wants_float(const std::string& ext) {
    return ext == ".exr" || ext == ".tif" || ext == ".tiff" || ext == ".EXR" || ext == ".TIF" ||
           ext == ".TIFF";
}

} // namespace

std::string write_image_atomic(const std::string& path, const ImageView& image) {
    const fs::path dest(path);
    std::error_code ec;
    if (fs::is_directory(dest, ec)) return path + ": is a folder, not a file";
    const std::string ext = dest.extension().string();
    const fs::path tmp = temporary_sibling(dest);
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out) return path + ": no image writer for '" + ext + "' (" + OIIO::geterror() + ")";
    const OIIO::TypeDesc type = wants_float(ext) ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    const bool jpeg = ext == ".jpg" || ext == ".jpeg" || ext == ".JPG" || ext == ".JPEG";
    // JPEG has no alpha channel: its three channels are read with a 4-float stride.
    OIIO::ImageSpec spec(image.width, image.height, jpeg ? 3 : 4, type);
    spec.attribute("oiio:ColorSpace", ext == ".exr" || ext == ".EXR" ? "Linear" : "sRGB");
    std::string error;
    if (!out->open(tmp.string(), spec)) {
        error = path + ": cannot write: " + out->geterror();
    } else if (!out->write_image(OIIO::TypeDesc::FLOAT, image.rgba.data(), 4 * sizeof(float))) {
        error = path + ": write failed: " + out->geterror();
    }
    if (!out->close() && error.empty()) error = path + ": write failed: " + out->geterror();
    out.reset();
    return finish_temporary(tmp, dest, std::move(error));
}

} // namespace casteljau
