#version 450 core
// Fast particles (media/particle_splat_pass.cpp): sorted billboards, back to front, carrying the
// fit of their source the lighting pass computed (common/splat_vertex.glsl).
// One particle a composited layer: the lamps' light takes the exact neighbour order (splat_source.glsl).
#define SPLAT_LAMP_ORDER
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/billboard.glsl"

layout(std430, binding = MEDIA_DRAW_ORDER_BINDING) readonly buffer DrawOrder { uint drawOrder[]; };
layout(std430, binding = MEDIA_PARTICLE_LIGHT_BINDING) readonly buffer ParticleLight { vec4 particleLight[]; };
#include "media/common/particle_light_layout.glsl"
#define SPLAT_VARYING out
#include "media/common/splat_varyings.glsl"
#include "media/common/splat_vertex.glsl"

layout(location = 12) uniform int uFirstRank;  // the draw's first rank: balanced draws runs by variant
#ifdef SPLAT_RANK_LIST
// The redraw at the edges (particle_splat_edges_pass.cpp) takes only the particles that reach them:
// uFirstRank indexes this list of ranks.
layout(std430, binding = MEDIA_SPLAT_RANKS_BINDING) readonly buffer SplatRanks { uint splatRanks[]; };
#endif

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

void main() {
#ifdef SPLAT_RANK_LIST
    int rank = int(splatRanks[uFirstRank + gl_InstanceID]);
#else
    int rank = uFirstRank + gl_InstanceID;
#endif
    splatVertex(rank, kCorners[gl_VertexID]);
#if defined(SPLAT_FAR_DEPTH)
    // A particle a mesh lies inside, drawn with this program where every surface lies behind its
    // sphere (the pass tests for a quad nearer than the scene): its farthest depth.
    vec4 farthest = frame.viewProjection * vec4(vCentreRadius.xyz + frame.cameraForward.xyz * vCentreRadius.w, 1.0);
    gl_Position.z = (farthest.w > 0.0 ? clamp(farthest.z / farthest.w, 0.0, 1.0) : 1.0) * gl_Position.w;
#elif !defined(SPLAT_DEPTH_TESTED)
    // Where the pass tests depth, a particle that fetches it takes its sphere's nearest depth (the
    // near plane's where that lies closer): the test then drops only what a surface hides whole.
    vec4 nearest = frame.viewProjection * vec4(vCentreRadius.xyz - frame.cameraForward.xyz * vCentreRadius.w, 1.0);
    gl_Position.z = (nearest.w > 0.0 ? min(nearest.z / nearest.w, 1.0) : 1.0) * gl_Position.w;
#endif
}
