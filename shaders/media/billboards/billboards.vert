#version 450 core
// `billboards` mode (media/billboard_pass.cpp), the yardstick a typical engine ships: sorted
// camera-facing sprites lit once per particle, at the vertices, by every light with its phase
// function; no medium transmittance and no mesh shadows on the particles.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "common/lights.glsl"
#include "media/common/optics.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/billboard.glsl"

layout(std430, binding = MEDIA_DRAW_ORDER_BINDING) readonly buffer DrawOrder { uint drawOrder[]; };

out vec2 vCorner;             // the billboard's corner coordinates, [−1, 1]²
flat out vec4 vSource;        // rgb: J, a: σR
flat out vec2 vDepthRadius;   // view depth of the centre, radius

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

void main() {
    GpuParticle particle = particles[drawOrder[gl_InstanceID]];
    vec4 pr = particle.positionRadius;
    vec2 corner = kCorners[gl_VertexID];
    vCorner = corner;
    vec3 toCentre;
    vec3 origin;
    cameraRayThrough(pr.xyz, origin, toCentre);
    vec3 scattered = frame.ambient.rgb;
    int i = 0;
    if (frame.counts.x > 0) do {  // not for: llvmpipe runs a for loop's body once more, masked
        LightSample s = sampleLight(i, pr.xyz);
        scattered += phaseValue(particle.extra.x, particle.emissionG.w, s.toLight, toCentre) * s.irradiance;
    } while (++i < frame.counts.x);
    vSource = vec4(particle.albedoSigma.rgb * scattered + particle.emissionG.rgb, particle.albedoSigma.w * pr.w);
    vSource.rgb = fogSeen(vSource.rgb, fogAtPoint(pr.xyz));
    vDepthRadius = vec2(dot(pr.xyz, frame.cameraForward.xyz), pr.w);
    Billboard b = billboardOf(pr.xyz, pr.w);
    gl_Position = billboardCornerClip(b, pr.xyz, corner);
}
