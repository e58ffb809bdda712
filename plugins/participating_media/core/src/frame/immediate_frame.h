#pragma once
// What MediaRenderer's calls for hosts without a frame graph keep between calls (immediate_frame.cpp).
#include <memory>

#include "frame/host_depth_pass.h"
#include "nimbus/gpu/texture_pool.h"
#include "nimbus/media/graph_frame.h"

namespace nimbus::media {

struct ImmediateFrame {
    gpu::TexturePool pool;
    GraphFrame frame;
    gpu::Texture sceneDepth, shadowMap;  // borrowed from the host
    const gpu::Texture* slices = nullptr;  // extracted from the graphs, handed back to the pool next frame
    const gpu::Texture* color = nullptr;
    const gpu::Texture* depthUsed = nullptr;
    const gpu::Texture* edges = nullptr;
    // The last frame's end: its uniform blocks are rewritten next frame, and llvmpipe does not order
    // a buffer update after queued draws that read it.
    GLsync previousFrame = nullptr;
    std::unique_ptr<HostDepthPass> hostDepth;  // a standard-Z host's depth re-encoded, made when first needed

    void giveBack(const gpu::Texture*& texture) {
        if (texture != nullptr) pool.release(texture);
        texture = nullptr;
    }

    void importShadowMap(gpu::FrameGraph& graph, const HostFrame& host) {
        frame.shadowMap = {};
        if (host.shadows == nullptr || host.shadows->texture == 0) return;
        int layers = 0;
        for (const auto& views : host.shadows->views) layers += static_cast<int>(views.size());
        shadowMap = gpu::Texture::borrow(host.shadows->texture, {GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, host.shadows->size,
                                                                 host.shadows->size, layers, 1});
        frame.shadowMap = graph.importTexture("host_shadow_map", shadowMap);
    }

    ~ImmediateFrame() {
        if (previousFrame != nullptr) glDeleteSync(previousFrame);
    }
};

}  // namespace nimbus::media
