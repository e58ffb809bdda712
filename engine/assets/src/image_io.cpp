#include "nimbus/assets/image_io.h"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/imageio.h>

#include "nimbus/base/error.h"

namespace nimbus::assets {
namespace {

std::string lowerExtension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

}  // namespace

float srgbEncode(float linear) {
    if (!(linear > 0.0f)) return 0.0f;  // also maps NaN to 0 for display
    if (linear >= 1.0f) return 1.0f;
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgbDecode(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

bool isLinearFormat(const std::filesystem::path& file) {
    const std::string ext = lowerExtension(file);
    return ext == ".exr" || ext == ".hdr" || ext == ".tif" || ext == ".tiff" || ext == ".pfm";
}

namespace {

// Writes w×h×3 `pixels` of `type` (FLOAT for linear formats, UINT8 display values otherwise).
void writePixels(const std::filesystem::path& file, int width, int height, OIIO::TypeDesc type, const void* pixels) {
    const std::string name = file.string();
    if (width <= 0 || height <= 0) throwInputError(name, "", "", "cannot write an empty image");
    if (file.has_parent_path()) {
        std::error_code ec;
        std::filesystem::create_directories(file.parent_path(), ec);
    }
    auto out = OIIO::ImageOutput::create(name);
    if (!out) throwInputError(name, "", "", "no image writer for this file extension (" + OIIO::geterror() + ")");
    OIIO::ImageSpec spec(width, height, 3, type);
    if (type == OIIO::TypeDesc::FLOAT) {
        spec.attribute("compression", "zip");
    } else {
        spec.attribute("oiio:ColorSpace", "sRGB");
    }
    if (!out->open(name, spec)) throwInputError(name, "", "", "cannot open for writing: " + out->geterror());
    if (!out->write_image(type, pixels)) throwInputError(name, "", "", "write failed: " + out->geterror());
    if (!out->close()) throwInputError(name, "", "", "close failed: " + out->geterror());
}

}  // namespace

void writeImage(const std::filesystem::path& file, const RgbImage& image, const ImageWriteOptions& options) {
    if (isLinearFormat(file)) return writePixels(file, image.width, image.height, OIIO::TypeDesc::FLOAT, image.rgb.data());
    writeDisplayPixels(file, image.width, image.height, displayEncode(image, options.exposure, options.curve));
}

float applyToneCurve(float x, ToneCurve curve) {
    if (curve == ToneCurve::None || !(x > 0.0f)) return x;
    // The fit overshoots 1 slightly past x ≈ 10 (its limit is 2.51/2.43): a display value stops at 1.
    return std::min(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 1.0f);
}

std::vector<std::uint8_t> displayEncode(const RgbImage& image, float exposure, ToneCurve curve) {
    std::vector<std::uint8_t> bytes(image.rgb.size());
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = static_cast<std::uint8_t>(std::lround(255.0f * srgbEncode(applyToneCurve(image.rgb[i] * exposure, curve))));
    return bytes;
}

void writeDisplayPixels(const std::filesystem::path& file, int width, int height, const std::vector<std::uint8_t>& rgb8) {
    if (rgb8.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3)
        throwInputError(file.string(), "", "", "pixel count does not match the image size");
    writePixels(file, width, height, OIIO::TypeDesc::UINT8, rgb8.data());
}

RgbImage readImage(const std::filesystem::path& file) {
    const std::string name = file.string();
    if (!std::filesystem::exists(file)) throwInputError(name, "", "", "no such file");
    auto in = OIIO::ImageInput::open(name);
    if (!in) throwInputError(name, "", "", "cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        throwInputError(name, "", "", "image has no pixels");

    const int channels = spec.nchannels;
    std::vector<float> pixels(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) *
                              static_cast<std::size_t>(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        throwInputError(name, "", "", "cannot decode image: " + in->geterror());
    const bool floatData = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF ||
                           spec.format.basetype == OIIO::TypeDesc::DOUBLE;
    in->close();

    RgbImage image(spec.width, spec.height);
    for (std::size_t p = 0; p < image.pixelCount(); ++p) {
        for (int c = 0; c < 3; ++c) {
            const float v = pixels[p * static_cast<std::size_t>(channels) + static_cast<std::size_t>(std::min(c, channels - 1))];
            image.rgb[p * 3 + static_cast<std::size_t>(c)] = floatData ? v : srgbDecode(v);
        }
    }
    return image;
}

}  // namespace nimbus::assets
