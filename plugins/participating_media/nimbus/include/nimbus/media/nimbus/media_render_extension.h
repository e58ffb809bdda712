#pragma once
// The media plugin in Nimbus's renderer: a render::RenderExtension that hands each frame to a
// MediaRenderer through the host contract (host.h, graph_frame.h), as any host would, inside the
// renderer's own frame graph (so `sandbox render --stats` times the plugin's passes).
//
// Does not: own the MediaRenderer (the ECS adapter or the caller does) or simulate.
#include "nimbus/media/graph_frame.h"
#include "nimbus/media/media_renderer.h"
#include "nimbus/render/scene_renderer.h"

namespace nimbus::media {

class MediaRenderExtension final : public render::RenderExtension {
public:
    explicit MediaRenderExtension(MediaRenderer& renderer) : renderer_(renderer) {}

    Aabb bounds() const override { return renderer_.bounds(); }
    void beforeOpaque(render::FrameGraph& graph, render::FrameContext& context) override;
    void afterOpaque(render::FrameGraph& graph, render::FrameContext& context) override;

private:
    MediaRenderer& renderer_;
    HostShadowMaps shadows_;
    GraphFrame frame_;  // read by the plugin's passes when the graph runs
};

// The contract's frame from the renderer's: camera, lights, environment, shadow views, and the mesh
// boxes when `occluders`. `shadows` receives the shadow views (its texture is the graph's, not a GL name).
HostFrame hostFrame(const render::FrameContext& context, HostShadowMaps& shadows, bool occluders);

}  // namespace nimbus::media
