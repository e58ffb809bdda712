#include "base_color.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "nimbus/assets/image_io.h"

namespace nimbus::media::reference {
namespace {

int wrapIndex(int i, int size, assets::Wrap wrap) {
    switch (wrap) {
        case assets::Wrap::ClampToEdge: return std::clamp(i, 0, size - 1);
        case assets::Wrap::MirroredRepeat: {
            const int period = 2 * size;
            int m = i % period;
            if (m < 0) m += period;
            return m < size ? m : period - 1 - m;
        }
        case assets::Wrap::Repeat:
        default: {
            int m = i % size;
            return m < 0 ? m + size : m;
        }
    }
}

}  // namespace

BaseColorSampler::BaseColorSampler(const assets::Scene& scene) : scene_(scene) {
    std::array<float, 256> decode{};
    for (int i = 0; i < 256; ++i) decode[static_cast<std::size_t>(i)] = assets::srgbDecode(static_cast<float>(i) / 255.0f);
    images_.resize(scene.images.size());
    for (std::size_t i = 0; i < scene.images.size(); ++i) {
        const assets::Image& src = scene.images[i];
        LinearImage& dst = images_[i];
        const std::size_t count = static_cast<std::size_t>(std::max(0, src.width)) * static_cast<std::size_t>(std::max(0, src.height));
        if (count == 0 || src.rgba8.size() < 4 * count) continue;
        dst.width = src.width;
        dst.height = src.height;
        dst.texels.resize(count);
        for (std::size_t t = 0; t < count; ++t)
            dst.texels[t] = {decode[src.rgba8[4 * t]], decode[src.rgba8[4 * t + 1]], decode[src.rgba8[4 * t + 2]]};
    }
}

glm::dvec3 BaseColorSampler::sampleTexture(int texture, glm::dvec2 uv) const {
    if (texture < 0 || static_cast<std::size_t>(texture) >= scene_.textures.size()) return glm::dvec3(1.0);
    const assets::Texture& tex = scene_.textures[static_cast<std::size_t>(texture)];
    if (tex.image < 0 || static_cast<std::size_t>(tex.image) >= images_.size()) return glm::dvec3(1.0);
    const LinearImage& img = images_[static_cast<std::size_t>(tex.image)];
    if (img.texels.empty() || !std::isfinite(uv.x) || !std::isfinite(uv.y)) return glm::dvec3(1.0);
    auto texel = [&](int x, int y) {
        const int wx = wrapIndex(x, img.width, tex.wrapS), wy = wrapIndex(y, img.height, tex.wrapT);
        return glm::dvec3(img.texels[static_cast<std::size_t>(wy) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(wx)]);
    };
    const double fx = uv.x * img.width - 0.5, fy = uv.y * img.height - 0.5;
    if (tex.magFilter == assets::Filter::Nearest)
        return texel(static_cast<int>(std::floor(fx + 0.5)), static_cast<int>(std::floor(fy + 0.5)));
    const double x0 = std::floor(fx), y0 = std::floor(fy);
    const double ax = fx - x0, ay = fy - y0;
    const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
    return (1.0 - ay) * ((1.0 - ax) * texel(ix, iy) + ax * texel(ix + 1, iy)) +
           ay * ((1.0 - ax) * texel(ix, iy + 1) + ax * texel(ix + 1, iy + 1));
}

glm::dvec3 BaseColorSampler::at(const raycast::MeshHit& hit) const {
    if (hit.material < 0 || static_cast<std::size_t>(hit.material) >= scene_.materials.size()) return glm::dvec3(1.0);
    const assets::Material& m = scene_.materials[static_cast<std::size_t>(hit.material)];
    glm::dvec3 color(m.baseColorFactor);
    if (m.baseColorTexture >= 0) {
        const bool second = m.baseColorTexCoord == 1;
        const bool has = second ? hit.hasTexcoord1 : hit.hasTexcoord0;
        color *= sampleTexture(m.baseColorTexture, has ? (second ? hit.texcoord1 : hit.texcoord0) : glm::dvec2(0.0));
    }
    return color;
}

}  // namespace nimbus::media::reference
