// The OpenImageIO module (libcasteljau_oiio.so): the OiioCodec of
// io/detail/oiio_codec.h over OpenImageIO 2.4. Built as a separate shared
// object that the library loads only when a file needs it; it exports one
// symbol, the entry point, and holds no state of its own.
#include "casteljau/io/detail/oiio_codec.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <filesystem>
#include <optional>

namespace casteljau::detail {
namespace {

class Reader final : public ImageReader {
  public:
    Reader(std::unique_ptr<OIIO::ImageInput> in, const OIIO::ImageSpec& spec,
           std::unique_ptr<OIIO::Filesystem::IOMemReader> memory)
        : memory_(std::move(memory)), in_(std::move(in)) {
        header_.width = spec.width, header_.height = spec.height, header_.depth = spec.depth;
        header_.channels = spec.nchannels;
        header_.straight = spec.get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;
        header_.orientation = spec.get_int_attribute("Orientation", 1);
        header_.linear = spec.get_string_attribute("oiio:ColorSpace") == "Linear";
    }
    const ImageHeader& header() const override { return header_; }
    std::string read(int channels, float* out, std::size_t stride) override {
        if (in_->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, out, OIIO::stride_t(stride)))
            return {};
        return in_->geterror();
    }

  private:
    // Declared first: the input reads from it until it is destroyed.
    std::unique_ptr<OIIO::Filesystem::IOMemReader> memory_;
    std::unique_ptr<OIIO::ImageInput> in_;
    ImageHeader header_;
};

class Codec final : public OiioCodec {
  public:
    OiioOpened open(const char* format, const std::string& name,
                    std::span<const unsigned char> memory, bool from_memory,
                    bool keep_straight) const override {
        OiioOpened r;
        auto in = OIIO::ImageInput::create(format ? std::string(format) : name);
        if (!in) {
            r.error = OIIO::geterror(), r.no_reader = true;
            return r;
        }
        OIIO::ImageSpec config;
        if (keep_straight) config.attribute("oiio:UnassociatedAlpha", 1);
        std::unique_ptr<OIIO::Filesystem::IOMemReader> proxy;
        if (from_memory) {
            proxy = std::make_unique<OIIO::Filesystem::IOMemReader>(memory.data(), memory.size());
            OIIO::Filesystem::IOProxy* p = proxy.get();
            config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &p);
        }
        OIIO::ImageSpec spec;
        if (!in->open(name, spec, config)) {
            r.error = in->geterror();
            return r;
        }
        r.reader = std::make_unique<Reader>(std::move(in), spec, std::move(proxy));
        return r;
    }

    // Into memory through an I/O proxy, when asked, or into the file.
    std::string write(const std::string& target, const OiioImage& image,
                      std::vector<unsigned char>* memory) const override {
        const std::string ext = std::filesystem::path(target).extension().string();
        auto out = OIIO::ImageOutput::create(target);
        if (!out) return "no image writer for '" + ext + "' (" + OIIO::geterror() + ")";
        std::optional<OIIO::Filesystem::IOVecOutput> proxy;
        if (memory) {
            proxy.emplace(*memory);
            if (!(out->supports("ioproxy") && out->set_ioproxy(&*proxy)))
                return "the '" + ext + "' writer cannot encode into memory";
        }
        const OIIO::TypeDesc file_type =
            image.float_file ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
        OIIO::ImageSpec spec(image.width, image.height, 4, file_type);
        spec.attribute("oiio:ColorSpace", image.linear ? "Linear" : "sRGB");
        // Unlabelled, OIIO takes the values as premultiplied.
        spec.attribute("oiio:UnassociatedAlpha", image.straight ? 1 : 0);
        const OIIO::TypeDesc given =
            image.float_pixels ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
        const OIIO::stride_t pixel_bytes(4 * given.size());
        std::string error;
        if (!out->open(target, spec))
            error = "cannot write: " + out->geterror();
        else if (!out->write_image(given, image.pixels, pixel_bytes))
            error = "write failed: " + out->geterror();
        if (!out->close() && error.empty()) error = "write failed: " + out->geterror();
        out.reset(); // before the proxy it may still hold
        return error;
    }
};

} // namespace
} // namespace casteljau::detail

extern "C" __attribute__((visibility("default"))) const casteljau::detail::OiioCodec*
casteljau_oiio_codec_v2() {
    static const casteljau::detail::Codec codec;
    return &codec;
}
