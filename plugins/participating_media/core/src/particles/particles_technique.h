#pragma once
// `particles`: camera-facing billboards sorted back to front, each a closed-form slab of its
// kernel lit through the light slices and the mesh shadow maps; per fragment in the exact tier,
// per particle (fitted across the billboard) in balanced and fast.
#include <cstdint>

#include "nimbus/base/quality_tier.h"
#include "nimbus/media/technique.h"

namespace nimbus::media {

// Where the particles are lit (the source J of docs/design.md §2), in the order of the lighting words.
enum class ParticleLighting : std::uint8_t {
    Fragment,       // per fragment, with every correction: the exact tier
    Particle,       // per particle at nine rays through its billboard, J fitted across it; light
                    // at each ray's shading point (phase, smooth mesh shadow, slices' transmittance)
    ParticleExact,  // as Particle, each ray shaded as Fragment shades a pixel
};

// With per-particle lighting, how the particles a mesh's box enters are lit (in the order of the
// cut_lighting words).
enum class CutLighting : std::uint8_t {
    Particles,  // per fragment over the whole particle, as the exact tier lights it
    Rays,       // per fragment only on the rays a surface may cut inside the sphere, the fit elsewhere
    Off,        // the fit (with the sun's mesh visibility per fragment in balanced)
};

struct ParticlesSettings {
    ParticleLighting lighting = ParticleLighting::Fragment;
    // With per-particle lighting: shade a frame per fragment after all where a lamp lies inside the
    // medium (lampInsideMedium). Off in every tier: the splats take a lamp's near field with the
    // exact tier's quadrature and neighbour order (docs/design-notes.md).
    bool exactNearLamps = false;
    bool softParticles = true;  // clip each particle's kernel at the opaque surface (off: billboard plane test)
    // Integrate the light's transmittance over each particle's layer (off: take it at one point:
    // faster (docs/PERFORMANCE.md), less exact for dense particles).
    bool layerLight = true;
    CutLighting cutLighting = CutLighting::Particles;

    static ParticlesSettings forTier(QualityTier tier);
};

TechniqueEntry particlesTechnique();

}  // namespace nimbus::media
