#include "casteljau/io/image_write.h"

#include "casteljau/io/atomic_file.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <filesystem>
#include <memory>
#include <span>
#include <system_error>
#include <utility>
#include <vector>

namespace casteljau {

namespace fs = std::filesystem;

namespace {

bool wants_float(const std::string& ext) {
    return ext == ".exr" || ext == ".tif" || ext == ".tiff" || ext == ".EXR" || ext == ".TIF" ||
           ext == ".TIFF";
}

std::vector<float> to_float(std::span<const std::uint8_t> rgba8) {
    std::vector<float> out(rgba8.size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = float(rgba8[i]) / 255.0f;
    return out;
}

std::vector<float> premultiplied(std::span<const float> rgba) {
    std::vector<float> out(rgba.begin(), rgba.end());
    for (std::size_t i = 0; i + 3 < out.size(); i += 4)
        for (int c = 0; c < 3; ++c) out[i + std::size_t(c)] *= out[i + 3];
    return out;
}

} // namespace

bool stores_float(const std::string& path) {
    return wants_float(fs::path(path).extension().string());
}

// Encodes with OIIO, either into memory (an I/O proxy) that
// write_file_atomic then writes with every step checked, or straight into the
// temporary file. Memory for PNG, JPEG and EXR: their encoders do not all
// report a failed write (the PNG writer ignores one; libjpeg's default handler
// exits the process). The file for TIFF: OIIO 2.4's memory proxy produces a
// TIFF whose directory offset is wrong, and libtiff reports failed writes.
std::string write_image_atomic(const std::string& path, const ImageView& image) {
    const fs::path dest(path);
    std::error_code ec;
    if (fs::is_directory(dest, ec)) return path + ": is a folder, not a file";
    const std::string ext = dest.extension().string();
    const bool tiff = ext == ".tif" || ext == ".tiff" || ext == ".TIF" || ext == ".TIFF";
    const fs::path target = tiff ? temporary_sibling(dest) : dest;
    auto out = OIIO::ImageOutput::create(target.string());
    if (!out) return path + ": no image writer for '" + ext + "' (" + OIIO::geterror() + ")";
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    if (!tiff && !(out->supports("ioproxy") && out->set_ioproxy(&memory)))
        return path + ": the '" + ext + "' writer cannot encode into memory";
    const OIIO::TypeDesc type = wants_float(ext) ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    const bool jpeg = ext == ".jpg" || ext == ".jpeg" || ext == ".JPG" || ext == ".JPEG";
    // JPEG has no alpha channel: its three channels are read with a 4-value stride.
    OIIO::ImageSpec spec(image.width, image.height, jpeg ? 3 : 4, type);
    const bool exr = ext == ".exr" || ext == ".EXR";
    spec.attribute("oiio:ColorSpace", exr ? "Linear" : "sRGB");
    // Unlabelled, OIIO takes the values as premultiplied: PNG would divide them by alpha.
    spec.attribute("oiio:UnassociatedAlpha", image.alpha == Alpha::straight ? 1 : 0);
    // 8-bit values go to an 8-bit format untouched; a float format gets floats.
    const bool bytes_in = image.rgba.empty() && !image.rgba8.empty();
    std::vector<float> widened;
    if (bytes_in && type == OIIO::TypeDesc::FLOAT) widened = to_float(image.rgba8);
    const std::span<const float> rgba = widened.empty() ? image.rgba : widened;
    // OIIO's EXR writer ignores that label (OpenEXR is premultiplied by definition).
    std::vector<float> converted;
    if (exr && image.alpha == Alpha::straight) converted = premultiplied(rgba);
    const bool as_bytes = bytes_in && widened.empty();
    const void* pixels = as_bytes            ? static_cast<const void*>(image.rgba8.data())
                         : converted.empty() ? static_cast<const void*>(rgba.data())
                                             : static_cast<const void*>(converted.data());
    const OIIO::TypeDesc given = as_bytes ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
    const std::size_t pixel_bytes = as_bytes ? 4 : 4 * sizeof(float);
    std::string error;
    if (!out->open(target.string(), spec)) {
        error = path + ": cannot write: " + out->geterror();
    } else if (!out->write_image(given, pixels, OIIO::stride_t(pixel_bytes))) {
        error = path + ": write failed: " + out->geterror();
    }
    if (!out->close() && error.empty()) error = path + ": write failed: " + out->geterror();
    out.reset();
    if (tiff) return finish_temporary(target, dest, std::move(error));
    if (!error.empty()) return error;
    return write_file_atomic(dest, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

} // namespace casteljau
