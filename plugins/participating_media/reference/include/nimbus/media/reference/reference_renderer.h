#pragma once
// The judge: a CPU renderer that computes docs/design.md §2 without bias, one ray per pixel centre.
//
//   L = ∫₀ᵈ T(0,t) Σ_i σ_i ρ_i(x) [ a_i (Σ_l p_i(θ_l) E_l V_l T_l + L_amb) + e_i ] dt + T(0,d) L_s
//
// is the single-scattering model, computed exactly as below. The multiple-scattering model (the
// scene's `scattering`, multiple by default) drops L_amb from that source and adds, by Monte Carlo,
// light scattered more than once, the environment of radiance L_amb attenuated and scattered, and
// emission scattered (scattering_paths.h): `spp` paths per pixel from collisions on the camera ray,
// each pixel with its standard error.
//
// Conventions (the real-time renderer matches them; see also camera_rays.h):
// - d: the first mesh hit within the camera's near/far planes (back faces of single-sided materials
//   are invisible); with no hit the medium runs to the far plane (or infinity) and L_s = background.
// - T(0,t): closed form (sum of per-particle erf expressions, optics.h).
// - E_l: assets::sampleLight (irradiance before visibility); V_l: Embree occlusion towards the light
//   up to its distance (every face blocks); T_l: closed-form transmittance towards the light through
//   all particles (a BVH finds them); optical depth beyond 64 counts as opaque (T < 2e-28).
// - cosθ_l = dot(light travel direction, -ray dir): g > 0 is bright looking towards the sun.
//   Henyey–Greenstein p = (1-g²)/(4π(1+g²-2g cosθ)^1.5); Rayleigh p = 3/(16π)(1+cos²θ).
// - Surface: L_s = Σ_l f(l, v) E_l max(0, n·l) V_l T_l + baseColor L_amb + emissive, f the glTF
//   metallic-roughness BRDF (assets/surface_brdf.h), v = −dir; baseColor (factor × texture ×
//   COLOR_0), metallic, roughness and emissive from assets/material_sampling.h. n: the
//   interpolated shading normal, flipped towards the viewer for double-sided materials. Surface
//   shadow rays start off the surface (MeshRaycaster::offsetFromSurface); T_l is taken at the hit.
//   MASK materials are cut away where their alpha is below alphaCutoff, for every ray (the ray
//   caster's filter).
// - Quadrature: the in-scattering integral is taken in the variable v = 1 - exp(-τ(t)) per cluster of
//   overlapping particles, where T σ_t dt = T(cluster start) dv exactly, so the integrand is the
//   (σ-weighted) source alone and the kernels' truncation steps and gaps between particles cost
//   nothing; t(v) is found by Newton on the closed-form τ. Globally adaptive Gauss–Kronrod (7/15),
//   starting from up to three intervals per cluster (cut at half its opacity and at its middle along
//   the ray, so a sparse tail that v compresses gets nodes of its own); the interval with the largest
//   |K15 - G7| is bisected until Σ|K15 - G7| <= tolerance × the pixel
//   value (max over RGB), or below an absolute floor of tolerance × 1e-3 × the scene's radiance scale
//   (brightest of background, ambient, emission, light irradiance/π at the scene centre) × the ray's
//   medium opacity (at most what the medium can send), or the
//   depth bound (48 bisections) is reached (counted as an unconverged ray).
// - Deterministic: each pixel depends only on the inputs (no shared accumulation), so the image has
//   the same bits for any thread count.
//
// Does not: light reflected or emitted by meshes into the medium or onto other meshes,
// anti-aliasing, motion blur, normal or occlusion textures, or image-based lighting.
#include <atomic>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/assets/image_io.h"
#include "nimbus/assets/scene.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/volume.h"

namespace nimbus::media::reference {

// Lets another thread watch a render (the editor's progress bar) and stop it early: a cancelled
// render returns with the tiles not yet started left black.
struct ReferenceProgress {
    std::atomic<int> tilesDone{0};
    std::atomic<int> tilesTotal{0};
    std::atomic<bool> cancel{false};
};

struct ReferenceSettings {
    int width = 0, height = 0;  // required
    double tolerance = 1e-4;    // relative change at which the quadrature stops
    int spp = 64;               // multiple scattering: paths per pixel (1..2^20)
    std::uint64_t seed = 1;     // multiple scattering: the paths' random streams
    std::optional<assets::Scattering> scattering;  // the model; empty: the scene's
    int threads = 0;            // 0: std::thread::hardware_concurrency()
    bool progress = true;       // progress bar on stderr (only drawn on a terminal)
    ReferenceProgress* watch = nullptr;  // optional, must outlive render()
};

struct ReferenceInputs {
    const assets::Scene* scene = nullptr;             // meshes, materials, textures, environment
    const std::vector<glm::dmat4>* world = nullptr;   // node transforms at the rendered time
    assets::ResolvedCamera camera;
    std::vector<assets::ResolvedLight> lights;
    const media::ParticleSet* particles = nullptr;    // world space; may be null (no medium)
    const std::vector<media::Volume>* volumes = nullptr;  // world space; may be null
};

// One ray's answer, for tests and diagnostics.
struct RayRadiance {
    glm::dvec3 radiance{0.0};     // L = transmittance · surface + inScattered
    glm::dvec3 surface{0.0};      // L_s (background with no hit); not computed (0) when transmittance is 0
    glm::dvec3 inScattered{0.0};  // the medium integral (its paths' mean included)
    glm::dvec3 paths{0.0};        // multiple scattering: the paths' mean, fogged
    glm::dvec3 standardError{0.0};  // of `paths`: their standard deviation over √spp
    double transmittance = 1.0;   // T(0, d)
    double opticalDepth = 0.0;    // τ(0, d)
    double distance = 0.0;        // d (+inf with no hit and no far plane)
    bool hitMesh = false;
    int evaluations = 0;          // source evaluations the quadrature used
    bool converged = true;        // false when the depth bound stopped the refinement
};

struct ReferenceStats {
    double seconds = 0.0;
    std::size_t evaluations = 0;
    std::size_t unconvergedPixels = 0;
    std::size_t paths = 0;                 // multiple scattering
    double meanStandardError = 0.0;        // over the pixels, of luminance
    double meanRadiance = 0.0;             // of luminance, for the error's scale
    bool multiple = false;                 // the model rendered
};

class ReferenceRenderer {
public:
    // Builds the mesh raycaster and the particle BVH. The inputs must outlive the renderer.
    ReferenceRenderer(const ReferenceInputs& inputs, const ReferenceSettings& settings);
    ~ReferenceRenderer();
    ReferenceRenderer(const ReferenceRenderer&) = delete;
    ReferenceRenderer& operator=(const ReferenceRenderer&) = delete;

    // The radiance along any ray: the medium from t = 0, meshes counted in [meshNear, meshFar].
    // `stream` picks the paths' random numbers (a pixel's index for tracePixel).
    RayRadiance traceRay(const glm::dvec3& origin, const glm::dvec3& dir, double meshNear, double meshFar,
                         std::uint64_t stream = 0) const;

    // The ray through pixel (x, y) of the settings' image size.
    RayRadiance tracePixel(int x, int y) const;

    // The whole image, multithreaded over tiles; `standardError`, when given, gets each pixel's.
    assets::RgbImage render(ReferenceStats* stats = nullptr, assets::RgbImage* standardError = nullptr) const;

    // Whether paths are traced (the multiple model with a medium).
    bool multiple() const;

    // Absolute radiance below which the quadrature stops refining (see the header comment).
    double absoluteFloor() const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

// Convenience: construct and render.
assets::RgbImage renderReference(const ReferenceInputs& inputs, const ReferenceSettings& settings,
                                 ReferenceStats* stats = nullptr, assets::RgbImage* standardError = nullptr);

}  // namespace nimbus::media::reference
