#include "common/frame_blocks.h"

#include <bit>
#include <cstddef>
#include <string>
#include <utility>

#include "nimbus/base/error.h"
#include "nimbus/gpu/light_views.h"

namespace nimbus::media {

// Uniform blocks are declared at their largest, so the buffers are too.
FrameBlocks::FrameBlocks()
    : frameBuffer_(gpu::createBuffer(sizeof(gpu::GpuFrame), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      lightsBuffer_(gpu::createBuffer(gpu::kMaxLights * sizeof(gpu::GpuLight), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      shadowViewsBuffer_(gpu::createBuffer(gpu::kMaxLightViews * sizeof(gpu::GpuLightView), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      sliceViews_(gpu::createBuffer(sizeof(GpuSliceViews), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      scatteringBuffer_(gpu::createBuffer(sizeof(GpuScattering), nullptr, GL_DYNAMIC_STORAGE_BIT)) {}

void FrameBlocks::packScattering(const GpuScattering& scattering, GLuint environment, GLuint directional) {
    scattering_ = scattering;
    environment_ = environment;
    directional_ = directional;
}

void checkCubeFaces(const HostShadowMaps& shadows) {
    static const char* const kFaces[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    for (std::size_t light = 0; light < shadows.views.size(); ++light) {
        const auto& views = shadows.views[light];
        if (views.size() != 6) continue;
        for (int f = 0; f < 6; ++f)
            if (!gpu::isCubeFaceView(f, views[static_cast<std::size_t>(f)]))
                throw InputError("HostShadowMaps::views of light " + std::to_string(light) + ": view " + std::to_string(f) +
                                 " is not the " + kFaces[f] + " cube face; a light's six views must be gpu::makeLightViews' "
                                 "faces, in its order (+X -X +Y -Y +Z -Z)");
    }
}

namespace {
// MediaSliceViews' first ivec4 (shaders/media/host/light_transmittance.glsl mediaSliceCount): x the
// view count, y a lamp view's share of the array's side, z its texels per side (0: the array's), w
// the largest uv a lookup takes in it; y and w as float bits, both 1 where every view is whole.
glm::ivec4 sliceHeader(std::size_t views, SliceArrayLayout layout) {
    const bool small = layout.lampTexels > 0 && layout.lampTexels < layout.arrayTexels;
    const float share = small ? static_cast<float>(layout.lampTexels) / static_cast<float>(layout.arrayTexels) : 1.0f;
    const float limit = small ? share - 0.5f / static_cast<float>(layout.arrayTexels) : 1.0f;
    return {static_cast<int>(views), std::bit_cast<int>(share), small ? layout.lampTexels : 0, std::bit_cast<int>(limit)};
}
}  // namespace

void FrameBlocks::pack(const HostFrame& host, const std::vector<gpu::GpuLightView>& sliceViews, const std::vector<glm::ivec2>& perLight,
                       SliceArrayLayout layout) {
    if (host.lights.size() > kMaxHostLights)
        throw InputError(std::to_string(host.lights.size()) + " lights in one frame; the media plugin takes at most " +
                         std::to_string(kMaxHostLights));
    const HostShadowMaps* shadows = host.shadows;
    if (shadows != nullptr) checkCubeFaces(*shadows);
    frame_ = gpu::packFrame(host.camera, host.ambient, host.background, static_cast<int>(host.lights.size()),
                            shadows ? shadows->size : 0, shadows ? shadows->pcfRadius : 0, host.fog);
    static const std::vector<std::vector<gpu::LightView>> kNoShadows;
    gpu::PackedLights packed = gpu::packLights(host.lights, host.camera.origin, shadows ? shadows->views : kNoShadows, shadows ? shadows->size : 0,
                                               shadows ? shadows->pointFaceSize : 0);
    lights_ = std::move(packed.lights);
    shadowViews_ = std::move(packed.shadowViews);
    perLight_.assign(host.lights.size(), glm::ivec4(-1, 0, 0, 0));
    for (std::size_t i = 0; i < perLight.size() && i < perLight_.size(); ++i)
        if (perLight[i].y > 0) perLight_[i] = glm::ivec4(perLight[i], 0, 0);
    views_ = sliceViews;
    sliceHeader_ = sliceHeader(views_.size(), layout);
    // Refused now, while the graph is set up, rather than half way through it.
    for (const auto& [count, what] : {std::pair{shadowViews_.size(), "shadow map views"}, std::pair{views_.size(), "light slice views"}})
        if (count > gpu::kMaxLightViews)
            throw InputError(std::to_string(count) + " " + what + " in one frame; the media plugin draws at most " +
                             std::to_string(gpu::kMaxLightViews));
}

void FrameBlocks::upload() const {
    glNamedBufferSubData(frameBuffer_.id(), 0, sizeof(gpu::GpuFrame), &frame_);
    gpu::uploadBlock(lightsBuffer_, gpu::kMaxLights, lights_, "lights");
    gpu::uploadBlock(shadowViewsBuffer_, gpu::kMaxLightViews, shadowViews_, "shadow map views");
    glNamedBufferSubData(sliceViews_.id(), 0, sizeof(sliceHeader_), &sliceHeader_);
    if (!perLight_.empty())
        glNamedBufferSubData(sliceViews_.id(), offsetof(GpuSliceViews, perLight), static_cast<GLsizeiptr>(perLight_.size() * sizeof(glm::ivec4)),
                             perLight_.data());
    if (!views_.empty())
        glNamedBufferSubData(sliceViews_.id(), offsetof(GpuSliceViews, views), static_cast<GLsizeiptr>(views_.size() * sizeof(gpu::GpuLightView)),
                             views_.data());
    if (environment_ != 0) glNamedBufferSubData(scatteringBuffer_.id(), 0, sizeof(GpuScattering), &scattering_);
}

void FrameBlocks::bind() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, gpu::kFrameUniformBinding, frameBuffer_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, gpu::kLightsBinding, lightsBuffer_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, gpu::kShadowViewsBinding, shadowViewsBuffer_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kSliceViewsBinding, sliceViews_.id());
    if (environment_ == 0) return;
    glBindBufferBase(GL_UNIFORM_BUFFER, kScatteringBinding, scatteringBuffer_.id());
    glBindTextureUnit(kEnvironmentUnit, environment_);
    glBindTextureUnit(kEnvironmentDirectionalUnit, directional_);
}

}  // namespace nimbus::media
