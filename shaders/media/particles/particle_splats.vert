#version 450 core
// Fast particles (media/particle_splat_pass.cpp): sorted billboards, back to front, carrying the
// fit of their source the lighting pass computed (particle_lighting.comp): its linear part
// interpolated across the quad, the rest for the fragments.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/billboard.glsl"

layout(std430, binding = MEDIA_DRAW_ORDER_BINDING) readonly buffer DrawOrder { uint drawOrder[]; };
layout(std430, binding = MEDIA_PARTICLE_LIGHT_BINDING) readonly buffer ParticleLight { vec4 particleLight[]; };
#include "media/common/particle_light_layout.glsl"

flat out vec4 vCentreRadius;  // origin-relative centre, radius
flat out float vSigma;
flat out float vFog;           // the fog factor at the centre (common/fog.glsl)
#ifdef SPLAT_CONSTANT
flat out vec4 vSource;        // F0
#else
out vec4 vSource;             // F0 + gx·x + gy·y (an affine function of the billboard's plane: exact)
out vec2 vCorner;             // x, y
flat out vec4 vFit[4];        // r2, r4, cx, cy
#endif
flat out vec4 vSun;           // rgb: albedo × the sun's radiance, a: the centre ray's shading offset
flat out vec2 vPhase;         // phase function (0 HG, 1 Rayleigh), g
#ifdef MEDIA_FRAGMENT_LAMPS
flat out vec3 vAlbedo;        // the lamps' light per fragment is scattered with it
#endif

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

void main() {
    int rank = gl_InstanceID;
    int index = int(drawOrder[rank]);
    GpuParticle particle = particles[index];
    vec4 pr = particle.positionRadius;
    vFog = fogAtPoint(pr.xyz);
    vCentreRadius = pr;
    vSigma = particle.albedoSigma.w;
    vPhase = vec2(particle.extra.x, particle.emissionG.w);
    uint base = PARTICLE_LIGHT_STRIDE * uint(rank);
    vSun = particleLight[base + SUN_SLOT];
#ifdef MEDIA_FRAGMENT_LAMPS
    vAlbedo = particle.albedoSigma.rgb;
#endif
    vec2 corner = kCorners[gl_VertexID];
    Billboard b = billboardOf(pr.xyz, pr.w);
#ifdef SPLAT_CONSTANT
    vSource = particleLight[base];
#else
    for (int k = 0; k < 4; ++k) vFit[k] = particleLight[base + 3u + uint(k)];
    vCorner = corner;
    vSource = particleLight[base];
    if (!b.coversScreen) vSource += particleLight[base + 1u] * corner.x + particleLight[base + 2u] * corner.y;
#endif
    if (b.coversScreen) {
        gl_Position = vec4(corner, 0.5, 1.0);
        return;
    }
    gl_Position = frame.viewProjection * vec4(pr.xyz + b.right * corner.x + b.up * corner.y, 1.0);
}
