#pragma once
// The host contract of the participating-media plugin (docs/integration.md): what a host engine
// gives the plugin each frame, as plain data and GL names, and what it gets back. The plugin packs
// its own uniform blocks from this data; it never reads the host's.
//
// A frame, in the host's order:
//   1. media::MediaRenderer::prepare(particles, settings)  — the particles to draw (simulated by the
//      plugin's EmitterSimulation or given by the host), and the settings.
//   2. renderLightSlices(frame)  — before the host's opaque pass: the medium's optical depth towards
//      each light. The host's mesh shader includes "media/host/light_transmittance.glsl" and
//      multiplies each light by mediaTransmittance(light, lightPosition, p), after
//      LightSlices::bind(): smoke then casts shadows on the host's meshes.
//   3. renderMedia(frame)  — after it, with frame.sceneDepth: the medium, into MediaLayer.
//   4. The host composes: pixel = layer.rgb + layer.a · opaque (premultiplied radiance, view
//      transmittance), upsampling with "common/upsample.glsl" when MediaLayer::depthUsed is set, and
//      taking MediaLayer::edges' texel instead within edgeRect where its alpha is ≥ 0. Outside
//      MediaLayer::coverRect the layer is empty, so it may compose only within it.
//
// Conventions: positions sent to the GPU are relative to HostFrame::camera.origin (double on the
// CPU). HostFrame::camera is the host's camera as the plugin draws with it: a gpu::View built from
// the host's pose, field of view and planes (gpu::makePerspectiveView), reversed Z. The host's own
// scene depth may be reversed Z (depth 1 at the near plane, cleared to 0) or standard (0 at the
// near plane, cleared to 1; either GL clip-depth mode gives the same window depth): say which in
// HostFrame::depthConvention. Shadow maps are reversed Z, drawn with gpu::LightView matrices.
//
// Does not: create a GL context, draw the host's meshes, present, or restore GL state: it binds its
// own programs, framebuffers, blocks (gpu/frame_layout.h points 0–2 included) and blend state, and
// the host sets what its next pass needs.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/base/aabb.h"
#include "nimbus/gpu/frame_layout.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/light_views.h"
#include "nimbus/gpu/view.h"

namespace nimbus::media {

// A punctual light in world space (KHR_lights_punctual resolved): kind, position or direction,
// radiance = colour × intensity, range, spot cone.
using Light = gpu::PunctualLight;

// The host's mesh shadow maps, optional. The media read them so smoke is shadowed by meshes.
struct HostShadowMaps {
    GLuint texture = 0;  // GL_TEXTURE_2D_ARRAY of GL_DEPTH_COMPONENT32F, reversed Z, one layer per view
    int size = 0;        // texels per side
    int pcfRadius = 1;   // the host's PCF radius (the media's smooth shadow does not use it)
    // Per light, in HostFrame::lights order, its views in layer order (empty: no shadow map). Views
    // from gpu::makeLightViews around the meshes plus MediaRenderer::bounds() cover everything. A
    // point light's six views must be makeLightViews' cube faces, in its order: the media find a
    // point's place in a face without the face's matrices (a frame with other faces is refused).
    std::vector<std::vector<gpu::LightView>> views;
    // Texels per side of a point light's faces, each drawn from its layer's first texel (0: size).
    // The media read a face only there, never the texel beyond it with a weight above 0. Last, so
    // a host's positional initialiser without it stays valid.
    int pointFaceSize = 0;
};

// A mesh's bounds in world space for `blocks` mode: its local box carried by the mesh's rotation
// and scale (a wing tilted through a cloud has an axis-aligned box as big as the cloud), or, where
// the transform shears, the axis-aligned box around that.
struct OccluderBox {
    glm::dvec3 centre{0.0};
    glm::dvec3 axis[3] = {glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(0.0, 0.0, 1.0)};  // orthonormal
    glm::dvec3 half{0.0};  // half extents along the axes
};
OccluderBox occluderBox(const glm::dmat4& world, const glm::dvec3& localMin, const glm::dvec3& localMax);
// The squared distance from p to the box (0 inside it).
double squaredDistance(const OccluderBox& box, const glm::dvec3& p);
// The half extents of the axis-aligned box around it.
glm::dvec3 axisAlignedHalf(const OccluderBox& box);

// The optical model the medium follows (the scene's `scattering`, docs/scene-format.md §2): multiple
// scattering (the plugin's approximation of light scattered any number of times, ambient an
// environment the medium attenuates), or single scattering (ambient unshadowed).
enum class ScatteringModel : std::uint8_t { Multiple, Single };

enum class DepthConvention : std::uint8_t {
    ReversedZ,  // Nimbus's: window depth 1 at the near plane, 0 at the far plane or infinity
    Standard,   // OpenGL's usual: 0 at the near plane, 1 at the far plane (or infinity)
};

struct HostFrame {
    gpu::View camera;           // viewport = camera.width × camera.height
    std::vector<Light> lights;  // at most kMaxHostLights; indices match the host's mesh shader
    glm::vec3 ambient{0.0f};    // L_amb, radiance every particle scatters (docs/design.md §2)
    glm::vec3 background{0.0f}; // what rays that hit nothing see
    ScatteringModel scattering = ScatteringModel::Multiple;
    // The scene's distance fog (scene-format.md §2.1): the plugin fogs each particle at its
    // distance; the host fogs its own meshes and background (shaders/common/fog.glsl does both).
    gpu::FogParams fog;
    GLuint sceneDepth = 0;      // GL_TEXTURE_2D depth of the opaque scene (renderMedia; 0: no media drawn)
    // How sceneDepth encodes depth, for the camera's planes. Standard costs one full-screen pass
    // (`media_host_depth`) that re-encodes it as the plugin reads depth.
    DepthConvention depthConvention = DepthConvention::ReversedZ;
    const HostShadowMaps* shadows = nullptr;
    // World boxes of the host's meshes: `blocks` mode shades the blocks they reach exactly, the
    // multiple-scattering model's environment is dark where one lies, and balanced `particles`
    // takes the sun's mesh visibility per fragment on the particles near them (elsewhere it stays
    // in the per-particle fit). Empty: the medium is taken as free of meshes (blocks: a seam may
    // show where one is seen inside).
    std::vector<OccluderBox> occluders;
    // Whether `occluders` boxes every mesh the scene depth holds. Then, at full resolution with a
    // reversed-Z depth texture, `particles` splats clear of every box are clipped by the depth test
    // alone, with no depth fetch (the same picture, faster); otherwise every splat fetches the depth.
    bool occludersComplete = false;
};

// What renderLightSlices returns; valid until the next renderLightSlices.
struct LightSlices {
    GLuint texture = 0;  // GL_TEXTURE_2D_ARRAY RGBA32F, two slices per layer beside their predecessors; 0: none this frame
    GLuint views = 0;    // the MediaSliceViews uniform block (nimbus/media/gpu_bindings.h)
    // Binds both at the points the host include expects (kSliceViewsBinding, kSlicesUnit, or the
    // host's own MEDIA_SLICE_VIEWS_BINDING / MEDIA_SLICES_UNIT). Harmless when there are none.
    void bind(GLuint viewsBinding, GLuint slicesUnit) const;
    void bind() const;
};

// What renderMedia returns; valid until the next renderMedia.
struct MediaLayer {
    GLuint color = 0;       // RGBA16F/32F, `size`: rgb premultiplied in-scattered radiance, a view transmittance
    GLuint depthUsed = 0;   // R32F view depth per texel when size is below the viewport, else 0
    // Mixed resolution: RGBA32F of at least edgeRect's size, or 0. Its texel t is the viewport's pixel
    // edgeRect.xy + t; where its alpha is ≥ 0 it holds the medium drawn at full resolution there
    // (the reduced layer's edges near a mesh), to take instead of upsampling.
    GLuint edges = 0;
    glm::ivec4 edgeRect{0};  // x, y (window pixels from the lower left), width, height
    // The viewport's pixels outside which the layer, upsampled, is empty (rgb 0, alpha 1: the pixel
    // is the opaque image), as edgeRect gives them; width 0: the whole viewport. A host may
    // compose only within it where nothing else (fog) changes the pixels outside.
    glm::ivec4 coverRect{0};
    glm::ivec2 size{0};
    float edgeThreshold = 0.2f;  // relative depth difference the depth-aware upsampling treats as an edge
};

}  // namespace nimbus::media
