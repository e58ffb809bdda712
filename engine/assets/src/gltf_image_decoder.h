#pragma once
// Decoding glTF images with OpenImageIO instead of tinygltf's bundled stb_image: a callback for
// tinygltf::TinyGLTF::SetImageLoader that decodes from memory (no temporary files) to RGBA8.
#include <string>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

namespace nimbus::assets {

// Passed as the callback's user data. The callback cannot throw through tinygltf, so it records
// the one-line refusal here and returns false; the loader rethrows it as an InputError.
struct ImageDecodeContext {
    const std::string* file = nullptr;
    const nlohmann::json* root = nullptr;  // for image names in messages
    std::string failure;                   // "file: images[2]: uri: ..." when decoding failed
};

// Largest accepted image side (larger ones are refused as absurd).
inline constexpr int kMaxImageSide = 16384;

// Signature of tinygltf::LoadImageDataFunction. Fills image->image with width × height × 4 bytes
// (grey and RGB expanded, alpha 255 where the file has none), row 0 at the top.
bool decodeGltfImage(tinygltf::Image* image, int imageIndex, std::string* err, std::string* warn, int requestedWidth,
                     int requestedHeight, const unsigned char* bytes, int size, void* context);

}  // namespace nimbus::assets
