#include "nimbus/media/nimbus/media_render_extension.h"

#include "nimbus/media/gpu_bindings.h"
#include "nimbus/render/frame_data.h"
#include "nimbus/render/light_views.h"

namespace nimbus::media {

HostFrame hostFrame(const render::FrameContext& context, HostShadowMaps& shadows, bool occluders) {
    HostFrame frame;
    frame.camera = context.view;
    frame.lights = render::punctualLights(context.input.lights);
    frame.ambient = context.input.environment.ambient;
    frame.background = context.input.environment.background;
    frame.scattering = context.input.environment.scattering == assets::Scattering::Single ? ScatteringModel::Single : ScatteringModel::Multiple;
    frame.fog = render::fogParams(context.input.environment.fog, context.view.zfar);
    shadows.texture = 0;
    shadows.size = context.settings.shadowMapSize;
    shadows.pointFaceSize = render::pointShadowSize(context.settings);
    shadows.pcfRadius = context.settings.pcfRadius;
    shadows.views = context.shadowViews;
    frame.shadows = &shadows;
    if (occluders && context.input.gpuScene != nullptr) {
        frame.occludersComplete = true;  // every instance's box
        for (const render::MeshInstance& instance : context.input.instances) {
            const auto& [lo, hi] = context.input.gpuScene->localBounds(instance.mesh);
            if (lo.x > hi.x) continue;  // a mesh without triangles
            frame.occluders.push_back(occluderBox(instance.world, glm::dvec3(lo), glm::dvec3(hi)));
        }
    }
    return frame;
}

void MediaRenderExtension::beforeOpaque(render::FrameGraph& graph, render::FrameContext& context) {
    frame_ = GraphFrame{};
    frame_.host = hostFrame(context, shadows_, renderer_.readsOccluders());
    frame_.shadowMap = context.shadowMap;
    renderer_.addLightSlices(graph, frame_);
    if (!frame_.slices.valid()) return;
    // The opaque pass's meshes receive the smoke's shadow through the plugin's GLSL host include.
    const GLuint views = frame_.blocks != nullptr ? renderer_.sliceViewsBlock() : 0;
    context.meshShading.push_back({"MEDIA_LIGHT_TRANSMITTANCE", {{kSlicesUnit, frame_.slices}},
                                   [views] { glBindBufferBase(GL_UNIFORM_BUFFER, kSliceViewsBinding, views); }});
    // A light with a slice crop (slice_crop): its meshes read the crop too, at a varying's cost
    // that frames without one do not pay (shaders/opaque.vert).
    if (renderer_.stats().slicesCropped > 0) context.meshShading.push_back({"MEDIA_SLICE_CROPS", {}, {}});
}

void MediaRenderExtension::afterOpaque(render::FrameGraph& graph, render::FrameContext& context) {
    frame_.sceneDepth = context.sceneDepth;
    // Compose fogs the opaque image under the layer, so with fog the medium keeps a layer.
    frame_.output = context.input.environment.fog.mode == assets::FogMode::None ? context.sceneColor : gpu::ResourceHandle{};
    renderer_.addMedia(graph, frame_);
    if (frame_.color.valid()) context.overlay = {frame_.color, frame_.depthUsed, frame_.edges, frame_.edgeRect, frame_.edgeThreshold, frame_.coverRect};
}

}  // namespace nimbus::media
