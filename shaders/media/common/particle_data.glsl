// The particle instance buffer (media/particle_buffer.h GpuParticle), positions relative to the
// frame origin.
#include "media/bindings.glsl"
struct GpuParticle {
    vec4 positionRadius;  // xyz origin-relative centre, w radius
    vec4 albedoSigma;     // rgb albedo, w peak extinction σ (1/m)
    vec4 emissionG;       // rgb emission, w phase asymmetry g
    vec4 extra;           // x phase (0 HG, 1 Rayleigh)
};

layout(std430, binding = MEDIA_PARTICLES_BINDING) readonly buffer Particles { GpuParticle particles[]; };
