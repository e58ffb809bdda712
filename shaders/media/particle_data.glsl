// The particle instance buffer (media/particle_buffer.h GpuParticle), positions relative to the
// frame origin.
struct GpuParticle {
    vec4 positionRadius;  // xyz origin-relative centre, w radius
    vec4 albedoSigma;     // rgb albedo, w peak extinction σ (1/m)
    vec4 emissionG;       // rgb emission, w phase asymmetry g
    vec4 extra;           // x phase (0 HG, 1 Rayleigh)
};

layout(std430, binding = 3) readonly buffer Particles { GpuParticle particles[]; };
