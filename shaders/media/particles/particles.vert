#version 450 core
// `particles` mode (media/particle_pass.cpp): sorted billboards, back to front. Each quad covers
// its particle's sphere on screen; the fragment shader integrates the kernel along the pixel's ray.
// PARTICLE_SPLAT_RUN: the splat pass's runs of the particles a mesh lies inside (particle_splat_pass.cpp).
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "media/common/particle_data.glsl"

layout(std430, binding = MEDIA_DRAW_ORDER_BINDING) readonly buffer DrawOrder { uint drawOrder[]; };

// x: the particle's index, y: its place in the draw order. One varying, not two: llvmpipe keeps
// setup data per varying per triangle, which a second one would add for every particle.
flat out ivec2 vParticle;
flat out float vFog;

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

#ifdef PARTICLE_SPLAT_RUN
// A run of the splats' draw ranks from uFirstRank (with SPLAT_RANK_LIST, of the edges' rank list).
layout(location = 12) uniform int uFirstRank;
#ifdef SPLAT_RANK_LIST
layout(std430, binding = MEDIA_SPLAT_RANKS_BINDING) readonly buffer SplatRanks { uint splatRanks[]; };
int drawRank() { return int(splatRanks[uFirstRank + gl_InstanceID]); }
#else
int drawRank() { return uFirstRank + gl_InstanceID; }
#endif
#else
int drawRank() { return gl_InstanceID; }
#endif

// The quad's corner: perpendicular to the eye→centre axis, sized to the tangent cone, so it covers
// the silhouette exactly.
vec4 billboardCorner(vec4 pr, vec2 corner) {
    vec3 c = (frame.viewMatrix * vec4(pr.xyz, 1.0)).xyz;
    if (frameOrthographic())
        return frame.viewProjection * vec4(pr.xyz + (frame.cameraRight.xyz * corner.x + frame.cameraUp.xyz * corner.y) * pr.w, 1.0);
    float d = length(c);
    // The eye is in or near the sphere, or the sphere crosses the near plane: cover the screen.
    if (d <= pr.w * 1.001 || -c.z - pr.w <= frame.depthParams.z * 2.0) return vec4(corner, 0.5, 1.0);
    vec3 axis = c / d;
    vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 right = normalize(cross(axis, helper));
    vec3 up = cross(right, axis);
    float half_ = pr.w * d / sqrt(d * d - pr.w * pr.w);
    vec3 p = c + (right * corner.x + up * corner.y) * half_;
    return frame.viewProjection * vec4((transpose(mat3(frame.viewMatrix)) * p), 1.0);
}

void main() {
    int rank = drawRank();
    int index = int(drawOrder[rank]);
    vParticle = ivec2(index, rank);
    vec4 pr = particles[index].positionRadius;
    vFog = fogAtPoint(pr.xyz);
    gl_Position = billboardCorner(pr, kCorners[gl_VertexID]);
#ifdef PARTICLE_SPLAT_RUN
    // Where the splat pass tests depth, this program draws where a surface lies in front of the
    // sphere's far side (the fit draws the rest): the quad at its farthest depth.
    vec4 farthest = frame.viewProjection * vec4(pr.xyz + frame.cameraForward.xyz * pr.w, 1.0);
    gl_Position.z = (farthest.w > 0.0 ? clamp(farthest.z / farthest.w, 0.0, 1.0) : 1.0) * gl_Position.w;
#endif
}
