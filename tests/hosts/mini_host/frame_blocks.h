#pragma once
// mini_host's own uniform blocks (shaders/mini_frame.glsl is their GLSL twin), packed from a
// FrameInput: positions camera-relative, light views in shadow-map layer order.
//
//   UBO binding 0  MiniFrame             view-projection, ambient, counts
//   UBO binding 1  MiniLights[64]        one per light
//   UBO binding 2  MiniShadowViews[384]  one per shadow-map layer
//   texture unit 1 the shadow map array (compare sampler)
// Units and bindings 2 and 3 stay free for the media include (MEDIA_SLICES_UNIT, MEDIA_SLICE_VIEWS_BINDING).
#include <glm/glm.hpp>

#include "frame_input.h"
#include "nimbus/gpu/gl_objects.h"

namespace mini {

inline constexpr GLuint kFrameBinding = 0, kLightsBinding = 1, kShadowViewsBinding = 2;
inline constexpr GLuint kShadowMapUnit = 1;
inline constexpr std::size_t kMaxLights = 64, kMaxShadowViews = 384;

struct alignas(16) FrameBlock {
    glm::mat4 viewProjection;
    glm::vec4 ambient;   // rgb
    glm::ivec4 counts;   // x lights, y shadow map size, z PCF radius
};

struct alignas(16) LightBlock {
    glm::vec4 position;   // xyz camera-relative, w range (0: infinite)
    glm::vec4 direction;  // xyz travel direction, w kind (0 directional, 1 point, 2 spot)
    glm::vec4 radiance;   // rgb colour × intensity
    glm::vec4 spot;       // x cone scale, y cone offset, z first shadow view (−1: none), w view count
};

struct alignas(16) ShadowViewBlock {
    glm::mat4 view;
    glm::mat4 viewProjection;
    glm::vec4 params;  // x perspective, y texel size in metres (at depth 1 when perspective), z layer
};

class FrameBlocks {
public:
    FrameBlocks();
    // Throws std::runtime_error past kMaxLights lights or kMaxShadowViews views.
    void upload(const FrameInput& frame);
    void bind() const;

private:
    nimbus::gpu::Buffer frame_, lights_, shadowViews_;
};

}  // namespace mini
