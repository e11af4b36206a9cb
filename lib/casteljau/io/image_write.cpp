#include "casteljau/io/image_write.h"

#include "casteljau/io/atomic_file.h"
#include "casteljau/io/detail/jpeg_write.h"
#include "casteljau/io/detail/oiio_module.h"
#include "casteljau/io/png_write.h"
#include "casteljau/paint/straight_rgba.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>
#include <new>
#include <span>
#include <system_error>
#include <utility>
#include <vector>

namespace casteljau {

namespace fs = std::filesystem;

namespace {

// ext: lowercased (image_extension).
bool wants_float(const std::string& ext) {
    return ext == ".exr" || ext == ".tif" || ext == ".tiff";
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

/// Why `image` does not hold width x height pixels of 4 values (floats, or
/// bytes when it has no floats); "" when it does.
std::string shape_error(const std::string& path, const ImageView& image) {
    const std::size_t values = image.rgba.empty() ? image.rgba8.size() : image.rgba.size();
    if (image.width > 0 && image.height > 0 &&
        values == std::size_t(image.width) * std::size_t(image.height) * 4)
        return {};
    return path + ": cannot write a " + std::to_string(image.width) + " x " +
           std::to_string(image.height) + " image from " + std::to_string(values) + " values";
}

/// PNG by the library's own encoder.
std::string write_png(const std::string& path, const ImageView& image) {
    if (std::string e = shape_error(path, image); !e.empty()) return e;
    const bool bytes_in = image.rgba.empty();
    const std::size_t n = std::size_t(image.width) * 4;
    try {
        PngRows rows(image.width, image.height);
        std::vector<Premul> row(std::size_t(image.width)); // a premultiplied row, as floats
        for (int y = 0; y < image.height; ++y) {
            std::uint8_t* out = rows.rgba(y);
            const std::size_t at = std::size_t(y) * n;
            const auto value = [&](std::size_t i) {
                return bytes_in ? float(image.rgba8[at + i]) / 255.0f : image.rgba[at + i];
            };
            if (image.alpha == Alpha::straight) {
                if (bytes_in)
                    std::copy_n(image.rgba8.data() + at, n, out);
                else
                    for (std::size_t i = 0; i < n; ++i) out[i] = channel_to_u8(value(i));
                continue;
            }
            // Premultiplied: divided by alpha in float first, as a canvas's
            // rows are (straight_rgba.h), not as OIIO did (dividing the
            // rounded bytes, which lost faint colors).
            for (std::size_t x = 0; x < row.size(); ++x)
                row[x] = {value(4 * x), value(4 * x + 1), value(4 * x + 2), value(4 * x + 3)};
            straight_row8(row.data(), image.width, out);
        }
        return write_png_atomic(path, std::move(rows));
    } catch (const std::bad_alloc&) {
        return path + ": out of memory";
    }
}

/// JPEG by libjpeg (detail/jpeg_write.h): the first three values of each
/// pixel as they are (JPEG has no alpha; canvas_write flattens onto white
/// first), floats rounded to 8 bits as for PNG (channel_to_u8).
std::string write_jpeg(const std::string& path, const ImageView& image) {
    if (std::string e = shape_error(path, image); !e.empty()) return e;
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    try {
        std::vector<std::uint8_t> rgb(3 * pixels);
        for (std::size_t i = 0; i < pixels; ++i)
            for (std::size_t c = 0; c < 3; ++c)
                rgb[3 * i + c] = image.rgba.empty() ? image.rgba8[4 * i + c]
                                                    : channel_to_u8(image.rgba[4 * i + c]);
        std::vector<unsigned char> bytes;
        if (std::string error = detail::encode_jpeg(image.width, image.height, rgb, bytes);
            !error.empty())
            return path + ": " + error;
        return write_file_atomic(fs::path(path),
                                 {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
    } catch (const std::bad_alloc&) {
        return path + ": out of memory";
    }
}

} // namespace

std::string image_extension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

bool stores_float(const std::string& path) { return wants_float(image_extension(path)); }

// PNG and JPEG by the library's own encoders; TIFF and EXR by OIIO (the
// module) either into memory, which write_file_atomic then writes with
// every step checked, or straight into the temporary file. Memory for EXR:
// its encoder does not report a failed write. The file for TIFF: OIIO
// 2.4's memory proxy produces a TIFF whose directory offset is wrong, and
// libtiff reports failed writes.
std::string write_image_atomic(const std::string& path, const ImageView& image) {
    const fs::path dest(path);
    std::error_code ec;
    if (fs::is_directory(dest, ec)) return path + ": is a folder, not a file";
    const std::string ext = image_extension(path);
    if (ext == ".png") return write_png(path, image);
    if (ext == ".jpg" || ext == ".jpeg") return write_jpeg(path, image);
    const bool tiff = ext == ".tif" || ext == ".tiff", exr = ext == ".exr";
    const detail::OiioModule& oiio = detail::oiio_module();
    if (!oiio.codec) return path + ": " + detail::oiio_missing("writing " + ext);
    // 8-bit values go to an 8-bit format untouched; a float format gets floats.
    const bool float_file = wants_float(ext);
    const bool bytes_in = image.rgba.empty() && !image.rgba8.empty();
    std::vector<float> widened;
    if (bytes_in && float_file) widened = to_float(image.rgba8);
    const std::span<const float> rgba = widened.empty() ? image.rgba : widened;
    // OIIO's EXR writer ignores the alpha label (OpenEXR is premultiplied by definition).
    std::vector<float> converted;
    if (exr && image.alpha == Alpha::straight) converted = premultiplied(rgba);
    const bool as_bytes = bytes_in && widened.empty();
    const void* pixels = as_bytes            ? static_cast<const void*>(image.rgba8.data())
                         : converted.empty() ? static_cast<const void*>(rgba.data())
                                             : static_cast<const void*>(converted.data());
    const detail::OiioImage request{.width = image.width,
                                    .height = image.height,
                                    .float_file = float_file,
                                    .float_pixels = !as_bytes,
                                    .pixels = pixels,
                                    .straight = image.alpha == Alpha::straight,
                                    .linear = exr};
    if (tiff) {
        const fs::path tmp = temporary_sibling(dest);
        std::string error = oiio.codec->write(tmp.string(), request, nullptr);
        return finish_temporary(tmp, dest, error.empty() ? error : path + ": " + error);
    }
    std::vector<unsigned char> bytes;
    if (std::string error = oiio.codec->write(path, request, &bytes); !error.empty())
        return path + ": " + error;
    return write_file_atomic(dest, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

} // namespace casteljau
