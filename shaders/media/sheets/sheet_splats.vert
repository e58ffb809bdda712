#version 450 core
// `sheets` mode (media/sheets/sheet_pass.cpp): the splats of the particles that reach into one
// sheet, the slab of view depth [uSheet.x, uSheet.y]. The draw covers the ranks whose centres lie
// within the largest radius of the sheet (the order is by view depth); the rest are dropped here.
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

layout(location = 2) uniform vec2 uSheet;    // the sheet's near and far view depth (m)
layout(location = 3) uniform int uFirstRank;  // the draw's first rank in the view-depth order

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

void main() {
    int rank = uFirstRank + gl_InstanceID;
    vec4 pr = particles[drawOrder[rank]].positionRadius;
    float depth = -(frame.viewMatrix * vec4(pr.xyz, 1.0)).z;
    if (depth + pr.w < uSheet.x || depth - pr.w > uSheet.y) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // all four corners at one point outside: nothing drawn
        return;
    }
    splatVertex(rank, kCorners[gl_VertexID]);
}
