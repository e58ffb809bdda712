#include "gltf_image_decoder.h"

#include <cstring>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "json_fields.h"
#include "nimbus/base/error.h"

namespace nimbus::assets {
namespace {

// OIIO picks its reader from a file name's extension; memory has none, so sniff the signature.
const char* formatBySignature(const unsigned char* bytes, std::size_t size) {
    if (size >= 8 && std::memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0) return "image.png";
    if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) return "image.jpg";
    if (size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WEBP", 4) == 0) return "image.webp";
    return nullptr;
}

std::string imageObject(const ImageDecodeContext& ctx, int index) {
    const auto i = static_cast<std::size_t>(index);
    if (ctx.root && ctx.root->contains("images") && (*ctx.root)["images"].is_array() && i < (*ctx.root)["images"].size())
        return describeObject("image", "images", i, (*ctx.root)["images"][i]);
    return "images[" + std::to_string(index) + "]";
}

std::string imageField(const tinygltf::Image& image) { return image.bufferView >= 0 ? "bufferView" : "uri"; }

bool refuse(ImageDecodeContext& ctx, std::string* err, int index, const tinygltf::Image& image, const std::string& problem) {
    ctx.failure = describeInputProblem(ctx.file ? *ctx.file : std::string(), imageObject(ctx, index), imageField(image), problem);
    if (err) *err += ctx.failure + "\n";
    return false;
}

}  // namespace

bool decodeGltfImage(tinygltf::Image* image, int imageIndex, std::string* err, std::string* /*warn*/,
                     int /*requestedWidth*/, int /*requestedHeight*/, const unsigned char* bytes, int size, void* context) {
    auto& ctx = *static_cast<ImageDecodeContext*>(context);
    if (size <= 0) return refuse(ctx, err, imageIndex, *image, "the image data is empty");
    const auto length = static_cast<std::size_t>(size);
    const char* name = formatBySignature(bytes, length);
    if (!name) return refuse(ctx, err, imageIndex, *image, "not a PNG, JPEG or WebP image");

    OIIO::Filesystem::IOMemReader proxy(bytes, length);
    // glTF colours are straight (unassociated) alpha; OIIO would premultiply PNG colour by alpha.
    // With a config, OIIO's readers take the proxy from the config too ("oiio:ioproxy").
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    OIIO::Filesystem::IOProxy* proxyPointer = &proxy;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxyPointer);
    auto in = OIIO::ImageInput::open(name, &config, &proxy);
    if (!in) return refuse(ctx, err, imageIndex, *image, "cannot decode the image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth != 1)
        return refuse(ctx, err, imageIndex, *image, "the image has no pixels");
    if (spec.width > kMaxImageSide || spec.height > kMaxImageSide)
        return refuse(ctx, err, imageIndex, *image,
                      std::to_string(spec.width) + "x" + std::to_string(spec.height) + " is larger than " +
                          std::to_string(kMaxImageSide) + " pixels on a side");

    const int channels = spec.nchannels;
    const std::size_t pixels = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
    std::vector<unsigned char> stored(pixels * static_cast<std::size_t>(channels));
    // UINT8 as stored: baseColor textures stay sRGB-encoded, 16-bit files are rescaled by OIIO.
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, stored.data()))
        return refuse(ctx, err, imageIndex, *image, "cannot decode the image: " + in->geterror());
    in->close();

    std::vector<unsigned char> rgba(pixels * 4);
    const auto ch = static_cast<std::size_t>(channels);
    for (std::size_t p = 0; p < pixels; ++p) {
        const unsigned char* s = stored.data() + p * ch;
        unsigned char* d = rgba.data() + p * 4;
        if (ch <= 2) {  // grey or grey + alpha
            d[0] = d[1] = d[2] = s[0];
            d[3] = ch == 2 ? s[1] : 255;
        } else {
            d[0] = s[0];
            d[1] = s[1];
            d[2] = s[2];
            d[3] = ch >= 4 ? s[3] : 255;
        }
    }
    image->width = spec.width;
    image->height = spec.height;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = std::move(rgba);
    image->as_is = false;
    return true;
}

}  // namespace nimbus::assets
