#pragma once
// Reading and writing images through OpenImageIO.
//
// EXR (and other float formats) hold linear radiance exactly as computed (32-bit float RGB).
// PNG/JPEG are display-encoded: L · exposure, clamped to [0, 1], sRGB transfer function, 8 bits.
// No tone curve is applied, so a PNG pixel is a plain function of the EXR pixel (docs/scene-format.md).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace nimbus::assets {

// Linear RGB radiance, row 0 at the top.
struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // width * height * 3

    RgbImage() = default;
    RgbImage(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, 0.0f) {}
    std::size_t pixelCount() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
    glm::vec3 at(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
    void set(int x, int y, const glm::vec3& v) {
        const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
        rgb[i] = v.x;
        rgb[i + 1] = v.y;
        rgb[i + 2] = v.z;
    }
};

// The tone curve display encoding applies after the exposure. None clamps at 1 (the documented
// default); Filmic is Narkowicz's fit of the ACES reference rendering transform,
// x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14), which rolls highlights off instead of clipping them.
enum class ToneCurve : std::uint8_t { None, Filmic };

struct ImageWriteOptions {
    float exposure = 1.0f;            // display-encoded formats only
    ToneCurve curve = ToneCurve::None;  // display-encoded formats only
};

// True for formats that store linear floats (.exr, .hdr, .tif/.tiff as float).
bool isLinearFormat(const std::filesystem::path& file);

// Writes by file extension. Throws nimbus::InputError (unwritable path, unknown format).
void writeImage(const std::filesystem::path& file, const RgbImage& image, const ImageWriteOptions& options = {});

// Display encoding as PNG writing does it: 8-bit sRGB of curve(L · exposure) clamped to [0, 1], RGB rows.
std::vector<std::uint8_t> displayEncode(const RgbImage& image, float exposure = 1.0f, ToneCurve curve = ToneCurve::None);
// The tone curve alone, per channel.
float applyToneCurve(float x, ToneCurve curve);

// Writes 8-bit RGB pixels that are already display values (a window screenshot), row 0 at the top.
void writeDisplayPixels(const std::filesystem::path& file, int width, int height, const std::vector<std::uint8_t>& rgb8);

// Reads any format OIIO knows. Display-encoded 8/16-bit files are decoded back to linear with the
// sRGB transfer function (no exposure is undone). Throws nimbus::InputError with the reason.
RgbImage readImage(const std::filesystem::path& file);

// sRGB transfer functions (IEC 61966-2-1), shared by the PNG writer, `compare` and the tests.
float srgbEncode(float linear);
float srgbDecode(float encoded);

}  // namespace nimbus::assets
