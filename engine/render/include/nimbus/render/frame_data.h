#pragma once
// The per-frame uniform and storage buffers every pass binds at fixed points, and their CPU mirror.
// Layouts match shaders/common/frame.glsl, lights.glsl, shadows.glsl and transmittance.glsl.
//
//   UBO  binding 0  Frame                  camera, viewport, depth linearisation, environment
//   UBO  binding 1  Lights[64]             one per light
//   UBO  binding 2  ShadowViews[384]       mesh shadow map views (layers of the shadow array)
//   UBO  binding 3  TransmittanceViews[384] medium optical-depth slice views (filled by a plugin)
//   texture unit 1  shadow map array (sampler2DArrayShadow)
//   texture unit 2  transmittance slices (sampler2DArray, RGBA32F, 4 slices per layer)
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/assets/scene.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/render/light_views.h"
#include "nimbus/render/view.h"

namespace nimbus::render {

inline constexpr GLuint kFrameUniformBinding = 0;
inline constexpr GLuint kLightsBinding = 1;               // uniform blocks, like the frame's
inline constexpr GLuint kShadowViewsBinding = 2;
inline constexpr GLuint kTransmittanceViewsBinding = 3;
inline constexpr std::size_t kMaxLights = 64;            // shaders/common/lights.glsl MAX_LIGHTS
inline constexpr std::size_t kMaxLightViews = 384;       // per kind; shaders/common/light_views.glsl MAX_LIGHT_VIEWS
inline constexpr GLuint kShadowMapUnit = 1;
inline constexpr GLuint kTransmittanceUnit = 2;
inline constexpr GLuint kSceneDepthUnit = 3;

struct alignas(16) GpuFrame {
    glm::mat4 viewProjection;
    glm::mat4 view;
    glm::mat4 inverseViewProjection;
    glm::vec4 cameraRight;    // w: tan(yfov/2)·aspect (perspective) or ortho half width
    glm::vec4 cameraUp;       // w: tan(yfov/2) or ortho half height
    glm::vec4 cameraForward;  // w: 1 orthographic, 0 perspective
    glm::vec4 depthParams;    // xy: View::depthLinearization(), z: near, w: far (0 = infinite)
    glm::vec4 viewport;       // width, height, 1/width, 1/height
    glm::vec4 ambient;        // rgb: L_amb
    glm::vec4 background;     // rgb: background radiance
    glm::ivec4 counts;        // x: lights, y: transmittance available (0/1), z: shadow map size, w: pcf radius
};

struct alignas(16) GpuLight {
    glm::vec4 position;   // xyz origin-relative, w: range (0 = infinite)
    glm::vec4 direction;  // xyz travel direction, w: type (0 directional, 1 point, 2 spot)
    glm::vec4 radiance;   // rgb: colour × intensity
    glm::vec4 spot;       // x: cone scale, y: cone offset, z: first shadow view (−1: none), w: shadow view count
    glm::vec4 media;      // x: first transmittance view (−1: none), y: view count
};

struct alignas(16) GpuLightView {
    glm::mat4 view;
    glm::mat4 viewProjection;
    glm::vec4 params;   // x: perspective, y: depth near, z: depth far, w: slice count (transmittance views)
    glm::vec4 params2;  // x: first texture layer, y: texel size in metres at depth 1 (shadow bias), zw: half extent
};

GpuLightView packLightView(const LightView& view, int firstLayer, float sliceCount, float texels);

// Transmittance slices a plugin provides for the frame: views per light (empty for unlit lights).
struct TransmittanceSlices {
    std::vector<GpuLightView> views;
    std::vector<glm::ivec2> perLight;  // (first view, count) per light index; count 0 = none
};

// Owns the buffers and rewrites them each frame.
class FrameData {
public:
    FrameData();
    void update(const View& view, const assets::Environment& environment,
                const std::vector<assets::ResolvedLight>& lights,
                const std::vector<std::vector<LightView>>& shadowViews, int shadowMapSize, int pcfRadius,
                const TransmittanceSlices* transmittance);
    void bind() const;  // binds the UBO and SSBOs at their binding points

    const GpuFrame& frame() const { return frame_; }

private:
    // Throws InputError naming `what` when there are more items than the block holds.
    template <typename T>
    void upload(gpu::Buffer& buffer, std::size_t capacity, const std::vector<T>& items, const char* what);

    GpuFrame frame_{};
    gpu::Buffer frameBuffer_;
    gpu::Buffer lights_, shadowViews_, transmittanceViews_;
};

}  // namespace nimbus::render
