#include "nimbus/assets/material_sampling.h"

#include <algorithm>
#include <cmath>

#include "nimbus/assets/image_io.h"

namespace nimbus::assets {
namespace {

int wrapIndex(int i, int size, Wrap wrap) {
    switch (wrap) {
        case Wrap::ClampToEdge: return std::clamp(i, 0, size - 1);
        case Wrap::MirroredRepeat: {
            const int period = 2 * size;
            int m = i % period;
            if (m < 0) m += period;
            return m < size ? m : period - 1 - m;
        }
        case Wrap::Repeat:
        default: {
            int m = i % size;
            return m < 0 ? m + size : m;
        }
    }
}

}  // namespace

MaterialSampler::MaterialSampler(const Scene& scene) : scene_(scene) {
    for (int i = 0; i < 256; ++i) srgb_[static_cast<std::size_t>(i)] = srgbDecode(static_cast<float>(i) / 255.0f);
}

const Material& MaterialSampler::material(int index) const {
    if (index < 0 || static_cast<std::size_t>(index) >= scene_.materials.size()) return default_;
    return scene_.materials[static_cast<std::size_t>(index)];
}

glm::dvec4 MaterialSampler::sampleTexture(int texture, const glm::dvec2& uv, bool srgb) const {
    if (texture < 0 || static_cast<std::size_t>(texture) >= scene_.textures.size()) return glm::dvec4(1.0);
    const Texture& tex = scene_.textures[static_cast<std::size_t>(texture)];
    if (tex.image < 0 || static_cast<std::size_t>(tex.image) >= scene_.images.size()) return glm::dvec4(1.0);
    const Image& img = scene_.images[static_cast<std::size_t>(tex.image)];
    const std::size_t count = static_cast<std::size_t>(std::max(0, img.width)) * static_cast<std::size_t>(std::max(0, img.height));
    if (count == 0 || img.rgba8.size() < 4 * count || !std::isfinite(uv.x) || !std::isfinite(uv.y)) return glm::dvec4(1.0);
    auto texel = [&](int x, int y) {
        const int wx = wrapIndex(x, img.width, tex.wrapS), wy = wrapIndex(y, img.height, tex.wrapT);
        const std::uint8_t* p = &img.rgba8[4 * (static_cast<std::size_t>(wy) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(wx))];
        if (srgb) return glm::dvec4(srgb_[p[0]], srgb_[p[1]], srgb_[p[2]], p[3] / 255.0);
        return glm::dvec4(p[0] / 255.0, p[1] / 255.0, p[2] / 255.0, p[3] / 255.0);
    };
    // Row 0 is the top of the image and v = 0 (glTF), so v indexes rows downwards.
    const double fx = uv.x * img.width - 0.5, fy = uv.y * img.height - 0.5;
    if (tex.magFilter == Filter::Nearest) return texel(static_cast<int>(std::floor(fx + 0.5)), static_cast<int>(std::floor(fy + 0.5)));
    const double x0 = std::floor(fx), y0 = std::floor(fy);
    const double ax = fx - x0, ay = fy - y0;
    const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
    return (1.0 - ay) * ((1.0 - ax) * texel(ix, iy) + ax * texel(ix + 1, iy)) + ay * ((1.0 - ax) * texel(ix, iy + 1) + ax * texel(ix + 1, iy + 1));
}

glm::dvec4 MaterialSampler::sampleRef(const TextureRef& ref, const SurfaceAttributes& at, bool srgb) const {
    if (!ref.present()) return glm::dvec4(1.0);
    return sampleTexture(ref.texture, ref.transform(ref.texCoord == 1 ? at.uv1 : at.uv0), srgb);
}

double MaterialSampler::alpha(int index, const SurfaceAttributes& at) const {
    const Material& m = material(index);
    return static_cast<double>(m.baseColorFactor.a) * at.color.a * sampleRef(m.baseColorTexture, at, true).a;
}

MaterialSample MaterialSampler::sample(int index, const SurfaceAttributes& at) const {
    const Material& m = material(index);
    MaterialSample s;
    s.baseColor = glm::dvec4(m.baseColorFactor) * at.color * sampleRef(m.baseColorTexture, at, true);
    const glm::dvec4 mr = sampleRef(m.metallicRoughnessTexture, at, false);
    s.metallic = m.metallicFactor * mr.b;
    s.roughness = m.roughnessFactor * mr.g;
    s.emissive = glm::dvec3(m.emissiveFactor) * glm::dvec3(sampleRef(m.emissiveTexture, at, true));
    return s;
}

}  // namespace nimbus::assets
