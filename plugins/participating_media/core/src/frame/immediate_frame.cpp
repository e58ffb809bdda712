// MediaRenderer's calls for hosts without a frame graph: each runs the plugin's passes on a graph
// of its own, with the host's textures borrowed into it and the results kept past it.
#include <memory>

#include "common/frame_blocks.h"
#include "frame/immediate_frame.h"
#include "nimbus/base/error.h"
#include "nimbus/gpu/pipeline_state.h"
#include "nimbus/media/media_renderer.h"

namespace nimbus::media {
namespace {

// The plugin's passes clip as reversed Z needs ([0, 1] clip depth); the host's mode is restored after.
class ClipDepthZeroToOne {
public:
    ClipDepthZeroToOne() {
        glGetIntegerv(GL_CLIP_ORIGIN, &origin_);
        glGetIntegerv(GL_CLIP_DEPTH_MODE, &depth_);
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    }
    ~ClipDepthZeroToOne() { glClipControl(static_cast<GLenum>(origin_), static_cast<GLenum>(depth_)); }
    ClipDepthZeroToOne(const ClipDepthZeroToOne&) = delete;
    ClipDepthZeroToOne& operator=(const ClipDepthZeroToOne&) = delete;

private:
    GLint origin_ = GL_LOWER_LEFT, depth_ = GL_ZERO_TO_ONE;
};

}  // namespace

LightSlices MediaRenderer::renderLightSlices(const HostFrame& host, gpu::PassTimer* timer) {
    if (!immediate_) immediate_ = std::make_unique<ImmediateFrame>();
    ImmediateFrame& im = *immediate_;
    const ClipDepthZeroToOne clip;
    if (im.previousFrame != nullptr) {
        glClientWaitSync(im.previousFrame, GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64{10'000'000'000});  // 10 s: a frame, not a hang
        glDeleteSync(im.previousFrame);
        im.previousFrame = nullptr;
    }
    im.giveBack(im.slices);
    im.frame = GraphFrame{};
    im.frame.host = host;
    gpu::FrameGraph graph(im.pool);
    im.importShadowMap(graph, host);
    addLightSlices(graph, im.frame);
    if (im.frame.slices.valid()) graph.extract(im.frame.slices);
    graph.compile();
    graph.execute(timer);
    if (im.frame.slices.valid()) im.slices = graph.extracted(im.frame.slices);
    gpu::applyPipeline({});  // the host's next pass starts from GL's defaults, whatever the last pass declared
    return {im.slices != nullptr ? im.slices->id() : 0, sliceViewsBlock()};
}

MediaLayer MediaRenderer::renderMedia(const HostFrame& host, gpu::PassTimer* timer) {
    if (!immediate_) throw std::logic_error("MediaRenderer::renderMedia before renderLightSlices in this frame");
    ImmediateFrame& im = *immediate_;
    const ClipDepthZeroToOne clip;
    im.giveBack(im.color);
    im.giveBack(im.depthUsed);
    im.giveBack(im.edges);
    im.frame.host = host;  // the slice views and uniform blocks stay from renderLightSlices
    gpu::FrameGraph graph(im.pool);
    im.importShadowMap(graph, host);
    im.frame.slices = im.slices != nullptr ? graph.importTexture("media_light_slices", *im.slices) : gpu::ResourceHandle{};
    MediaLayer layer;
    if (host.sceneDepth != 0) {
        im.sceneDepth = gpu::Texture::borrow(host.sceneDepth, {GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, host.camera.width, host.camera.height, 1, 1});
        im.frame.sceneDepth = graph.importTexture("host_scene_depth", im.sceneDepth);
        if (host.depthConvention == DepthConvention::Standard) {
            if (!im.hostDepth) im.hostDepth = std::make_unique<HostDepthPass>();
            im.frame.sceneDepth = im.hostDepth->add(graph, im.frame.sceneDepth, host.camera);
        }
        addMedia(graph, im.frame);
    }
    if (im.frame.color.valid()) graph.extract(im.frame.color);
    if (im.frame.depthUsed.valid()) graph.extract(im.frame.depthUsed);
    if (im.frame.edges.valid()) graph.extract(im.frame.edges);
    graph.compile();
    graph.execute(timer);
    if (im.frame.color.valid()) im.color = graph.extracted(im.frame.color);
    if (im.frame.depthUsed.valid()) im.depthUsed = graph.extracted(im.frame.depthUsed);
    if (im.frame.edges.valid()) im.edges = graph.extracted(im.frame.edges);
    im.pool.endFrame();
    gpu::applyPipeline({});
    im.previousFrame = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    if (im.color != nullptr) {
        layer.color = im.color->id();
        layer.size = {im.color->desc().width, im.color->desc().height};
        layer.depthUsed = im.depthUsed != nullptr ? im.depthUsed->id() : 0;
        layer.edges = im.edges != nullptr ? im.edges->id() : 0;
        layer.edgeRect = im.edges != nullptr ? im.frame.edgeRect : glm::ivec4(0);
        layer.edgeThreshold = im.frame.edgeThreshold;
        layer.coverRect = im.frame.coverRect;
    }
    return layer;
}

}  // namespace nimbus::media
