#include "casteljau/io/image_write.h"

#include <OpenImageIO/imageio.h>
#include <filesystem>
#include <memory>
#include <system_error>
#include <unistd.h>

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
    // Same folder (rename is atomic only within a file system), same extension.
    // Built by appending: GCC 12 warns falsely (-Wrestrict, PR 105329) on the
    // equivalent chain of operator+ with a leading literal.
    std::string name(".");
    name.append(dest.stem().string()).append(".tmp-").append(std::to_string(::getpid()));
    name.append(ext);
    const fs::path tmp = dest.parent_path() / name;
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
    if (error.empty()) {
        fs::rename(tmp, dest, ec);
        if (ec) error = path + ": cannot move the finished image into place: " + ec.message();
    }
    if (!error.empty()) fs::remove(tmp, ec);
    return error;
}

} // namespace casteljau
