#version 450 core
// Fast particles (media/particle_splat_pass.cpp): sorted billboards, back to front, carrying the
// fit of their source the lighting pass computed (common/splat_vertex.glsl).
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

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

void main() { splatVertex(uFirstRank + gl_InstanceID, kCorners[gl_VertexID]); }
