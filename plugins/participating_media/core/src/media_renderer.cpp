#include "nimbus/media/media_renderer.h"

#include <algorithm>

#include "media_passes.h"
#include "nimbus/base/error.h"
#include "nimbus/media/slice_plan.h"
#include "particle_buffer.h"

namespace nimbus::media {

MediaMode parseMediaMode(const std::string& text, const std::string& origin) {
    if (text == "particles") return MediaMode::Particles;
    throwInputError(origin, text, "", "unknown media mode (known: particles)");
}

const char* mediaModeName(MediaMode mode) {
    switch (mode) {
        case MediaMode::Particles: return "particles";
    }
    return "unknown";
}

assets::Aabb particleBounds(const ParticleSet& particles) {
    assets::Aabb bounds;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 r(particles.radius[i]);
        bounds.extend(particles.position[i] - r);
        bounds.extend(particles.position[i] + r);
    }
    return bounds;
}

MediaRenderer::MediaRenderer() = default;
MediaRenderer::~MediaRenderer() = default;

void MediaRenderer::prepare(const ParticleSet& particles, const MediaRenderSettings& settings) {
    particles_ = &particles;
    settings_ = settings;
    bounds_ = particleBounds(particles);
    stats_ = {};
    stats_.particles = particles.size();
}

void MediaRenderer::beforeOpaque(render::FrameGraph& graph, render::FrameContext& context) {
    if (particles_ == nullptr || particles_->empty()) return;
    if (!buffer_) buffer_ = std::make_unique<ParticleGpuBuffer>();

    struct Upload {};
    graph.addPass<Upload>(
        "media_upload", [](render::PassBuilder& builder, Upload&) { builder.sideEffect(); },
        [this, &context](const render::PassResources&, const Upload&) {
            buffer_->upload(*particles_, context.view.origin);
            buffer_->sortBackToFront(*particles_, context.view);
        });

    const int resolution = settings_.sliceResolution > 0 ? settings_.sliceResolution : 256;
    std::vector<SliceView> views;
    int layers = 0;
    context.transmittance.perLight.assign(context.input.lights.size(), glm::ivec2(0));
    for (std::size_t i = 0; i < context.input.lights.size(); ++i) {
        const auto& light = context.input.lights[i];
        if (light.params.range > 0.0 && light.params.type != assets::LightType::Directional) {
            const glm::dvec3 nearest = glm::clamp(light.position, bounds_.min, bounds_.max);
            if (glm::length(nearest - light.position) >= light.params.range) continue;  // out of reach
        }
        const auto lightViews = render::makeLightViews(light, bounds_, context.view.origin);
        context.transmittance.perLight[i] = glm::ivec2(static_cast<int>(context.transmittance.views.size()),
                                                       static_cast<int>(lightViews.size()));
        for (auto view : lightViews) {
            const SliceEstimate estimate = estimateSlices(*particles_, view, context.view.origin);
            const int slices = settings_.slices > 0 ? std::clamp(settings_.slices, kMinSlices, kMaxSlices) : estimate.slices;
            view.depthNear = static_cast<float>(estimate.depthNear);
            view.depthFar = static_cast<float>(estimate.depthFar);
            views.push_back({view, glm::vec3(light.position - context.view.origin), slices, layers});
            context.transmittance.views.push_back(
                render::packLightView(view, layers, static_cast<float>(slices), static_cast<float>(resolution)));
            layers += (slices + 3) / 4;
            stats_.slices = std::max(stats_.slices, slices);
        }
    }
    stats_.sliceViews = static_cast<int>(views.size());
    if (views.empty()) return;
    if (!slicePass_) slicePass_ = std::make_unique<LightSlicePass>();
    context.transmittanceSlices = slicePass_->add(graph, views, resolution, *buffer_);
}

void MediaRenderer::afterOpaque(render::FrameGraph& graph, render::FrameContext& context) {
    if (particles_ == nullptr || particles_->empty()) return;
    if (!particlePass_) particlePass_ = std::make_unique<ParticlePass>();
    particlePass_->add(graph, context, *buffer_, settings_.softParticles);
}

}  // namespace nimbus::media
