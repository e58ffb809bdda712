#pragma once
// The plugin inside a host's frame graph (nimbus/gpu/frame_graph.h): the graph half of the host
// contract. Nimbus's renderer uses it (plugins/participating_media/nimbus); MediaRenderer's
// renderLightSlices/renderMedia run it on a graph of their own for hosts without one.
//
// Does not: outlive the frame. The passes read it when the graph executes, so it must stay where
// it is from addLightSlices until the graph has run.
#include <vector>

#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/frame_layout.h"
#include "nimbus/media/host.h"

namespace nimbus::media {

class FrameBlocks;

struct GraphFrame {
    HostFrame host;                  // sceneDepth and shadows->texture are not read: the handles below are
    gpu::ResourceHandle sceneDepth;  // the opaque scene's depth in the graph (needed by addMedia)
    gpu::ResourceHandle shadowMap;   // the mesh shadow map array in the graph; invalid: none
    // The host's linear output holding the opaque image, where the host lets a full-resolution
    // medium blend straight over it (alpha kept) rather than hand back a layer; invalid: a layer.
    gpu::ResourceHandle output;

    // Filled by the plugin.
    gpu::ResourceHandle slices;          // addLightSlices: the light slices; invalid: none this frame
    gpu::ResourceHandle color;           // addMedia: MediaLayer::color (invalid: none, or drawn over `output`)
    gpu::ResourceHandle depthUsed;       // addMedia: MediaLayer::depthUsed (invalid at full resolution)
    gpu::ResourceHandle edges;           // addMedia: MediaLayer::edges (invalid: none)
    glm::ivec4 edgeRect{0};              // addMedia: MediaLayer::edgeRect
    glm::ivec4 coverRect{0};             // addMedia: MediaLayer::coverRect
    float edgeThreshold = 0.2f;          // addMedia: MediaLayer::edgeThreshold
    std::vector<gpu::GpuLightView> sliceViews;  // addLightSlices: every light's slice views
    bool multiple = false;                      // addLightSlices: the frame draws the multiple-scattering model
    const FrameBlocks* blocks = nullptr;        // the plugin's uniform blocks for this frame
};

}  // namespace nimbus::media
