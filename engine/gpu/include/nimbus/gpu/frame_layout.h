#pragma once
// The camera, light and light-view uniform blocks Nimbus's shaders share (shaders/common/frame.glsl,
// lights.glsl, light_views.glsl), their fixed binding points, and the one packing of each. The
// engine packs them for its passes and the media plugin packs its own copies from a host's data.
//
//   UBO  binding 0  Frame              camera, viewport, depth linearisation, environment
//   UBO  binding 1  Lights[64]         one per light
//   UBO  binding 2  ShadowViews[384]   mesh shadow map views (layers of the shadow array)
//   texture unit 1  shadow map array (sampler2DArrayShadow)
//   texture unit 3  scene depth (reversed Z)
//
// Does not: own buffers (render::FrameData and the plugin do) or declare a plugin's own blocks.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/light_views.h"
#include "nimbus/gpu/view.h"

namespace nimbus::gpu {

inline constexpr GLuint kFrameUniformBinding = 0;
inline constexpr GLuint kLightsBinding = 1;
inline constexpr GLuint kShadowViewsBinding = 2;
inline constexpr std::size_t kMaxLights = 64;       // shaders/common/lights.glsl MAX_LIGHTS
inline constexpr std::size_t kMaxLightViews = 384;  // per block; shaders/common/light_views.glsl MAX_LIGHT_VIEWS
inline constexpr GLuint kShadowMapUnit = 1;
inline constexpr GLuint kSceneDepthUnit = 3;

// Distance fog as the shaders take it (shaders/common/fog.glsl, scene-format.md §2.1).
enum class FogKind : int { None = 0, Exp = 1, Exp2 = 2, Linear = 3, Height = 4 };
struct FogParams {
    FogKind kind = FogKind::None;
    glm::vec3 color{0.0f};
    float density = 0.0f, start = 0.0f, end = 0.0f, falloff = 0.0f;
    double base = 0.0;                // world height (height fog)
    double backgroundDistance = 0.0;  // how far rays that hit nothing see fog; 0: infinitely far
};

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
    glm::ivec4 counts;        // x: lights, y: unused, z: shadow map size, w: pcf radius
    glm::vec4 fogColor;       // rgb: fog colour, w: FogKind
    glm::vec4 fogParams;      // density, start, end, falloff
    glm::vec4 fogHeight;      // x: frame origin height above the fog's base, y: background distance (1e30: infinite)
};

struct alignas(16) GpuLight {
    glm::vec4 position;   // xyz origin-relative, w: range (0 = infinite)
    glm::vec4 direction;  // xyz travel direction, w: type (0 directional, 1 point, 2 spot)
    glm::vec4 radiance;   // rgb: colour × intensity
    glm::vec4 spot;       // x: cone scale, y: cone offset, z: first shadow view (−1: none), w: shadow view count
};

struct alignas(16) GpuLightView {
    glm::mat4 view;
    glm::mat4 viewProjection;
    // x: perspective, y: depth near, z: depth far; w: slice count (transmittance views), or the share of
    // its layer's side a shadow view is drawn in, from the layer's first texel (1: all of it)
    glm::vec4 params;
    glm::vec4 params2;  // x: first texture layer, y: texel size in metres at depth 1 (shadow bias), zw: half extent
};

GpuFrame packFrame(const View& view, const glm::vec3& ambient, const glm::vec3& background, int lights, int shadowMapSize,
                   int pcfRadius, const FogParams& fog = {});
// `firstShadowView` −1: no shadow map.
GpuLight packLight(const PunctualLight& light, const glm::dvec3& origin, int firstShadowView, int shadowViews);
GpuLightView packLightView(const LightView& view, int firstLayer, float sliceCount, float texels);

// Every light with its shadow views (per light, in layer order; a light without views, or past the
// end of `shadowViews`, has no shadow map), as the Lights and ShadowViews blocks hold them. A point
// light's six faces are drawn in the first `pointFaceSize` texels of their layers' sides (0: all
// `shadowMapSize`).
struct PackedLights {
    std::vector<GpuLight> lights;
    std::vector<GpuLightView> shadowViews;
};
PackedLights packLights(const std::vector<PunctualLight>& lights, const glm::dvec3& origin,
                        const std::vector<std::vector<LightView>>& shadowViews, int shadowMapSize, int pointFaceSize = 0);
// The side, in texels from its layer's first, that a light's shadow views are drawn in: a point
// light's faces `pointFaceSize` (0: all), every other view the whole `shadowMapSize`. The shadow
// pass draws by it and packLights tells the lookups.
int shadowViewSide(LightKind kind, int shadowMapSize, int pointFaceSize);

// Writes `count` items of `itemSize` bytes at the start of `buffer`; throws InputError naming
// `what` when there are more than the block holds (`capacity`).
void uploadBlock(GLuint buffer, std::size_t capacity, const void* items, std::size_t count, std::size_t itemSize, const char* what);
template <typename T>
void uploadBlock(const Buffer& buffer, std::size_t capacity, const std::vector<T>& items, const char* what) {
    uploadBlock(buffer.id(), capacity, items.data(), items.size(), sizeof(T), what);
}

}  // namespace nimbus::gpu
