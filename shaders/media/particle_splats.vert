#version 450 core
// Fast particles (media/particle_splat_pass.cpp): sorted billboards, back to front, carrying the
// source their lighting pass computed as a linear field over the quad.
#include "common/math.glsl"
#include "common/frame.glsl"
#include "media/particle_data.glsl"
#include "media/billboard.glsl"

layout(std430, binding = 5) readonly buffer DrawOrder { uint drawOrder[]; };
layout(std430, binding = 10) readonly buffer ParticleLight { vec4 particleLight[]; };
#include "media/particle_light_layout.glsl"

flat out vec4 vCentreRadius;  // origin-relative centre, radius
flat out float vSigma;
out vec3 vSource;             // J's linear part (an affine function of the billboard's plane: exact)
flat out vec3 vRadial;        // J's radial part per β²
flat out vec3 vQuartic, vCubicX, vCubicY;
out vec2 vCorner;
#ifdef MEDIA_FRAGMENT_LAMPS
flat out vec3 vLampFactor[MAX_FRAGMENT_LAMPS];
flat out vec3 vPhase;         // x: phase function (0 HG, 1 Rayleigh), y: g, z: shading offset along the ray
#endif

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

void main() {
    int rank = gl_InstanceID;
    int index = int(drawOrder[rank]);
    vec4 pr = particles[index].positionRadius;
    vCentreRadius = pr;
    vSigma = particles[index].albedoSigma.w;
    vec2 corner = kCorners[gl_VertexID];
    uint base = PARTICLE_LIGHT_STRIDE * uint(rank);
    vec3 j0 = particleLight[base].rgb;
    vRadial = particleLight[base + 3u].rgb;
    vQuartic = particleLight[base + 4u].rgb;
    vCubicX = particleLight[base + 5u].rgb;
    vCubicY = particleLight[base + 6u].rgb;
    vCorner = corner;
#ifdef MEDIA_FRAGMENT_LAMPS
    for (int k = 0; k < MAX_FRAGMENT_LAMPS; ++k) vLampFactor[k] = particleLight[base + 7u + uint(k)].rgb;
    vPhase = vec3(particles[index].extra.x, particles[index].emissionG.w, particleLight[base].w);
#endif
    Billboard b = billboardOf(pr.xyz, pr.w);
    if (b.coversScreen) {
        vSource = j0;
        gl_Position = vec4(corner, 0.5, 1.0);
        return;
    }
    vSource = j0 + particleLight[base + 1u].rgb * corner.x + particleLight[base + 2u].rgb * corner.y;
    gl_Position = frame.viewProjection * vec4(pr.xyz + b.right * corner.x + b.up * corner.y, 1.0);
}
