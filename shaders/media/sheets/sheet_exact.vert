#version 450 core
// The exact tier of `sheets` mode (media/sheets/sheet_pass.cpp): the billboards of the particles
// that reach into one sheet, the slab of view depth [uSheet.x, uSheet.y]; the draw covers the
// ranks within the largest radius of it (the order is by view depth), the rest are dropped here.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/billboard.glsl"

layout(std430, binding = MEDIA_DRAW_ORDER_BINDING) readonly buffer DrawOrder { uint drawOrder[]; };

layout(location = 2) uniform vec2 uSheet;    // the sheet's near and far view depth (m)
layout(location = 3) uniform int uFirstRank;  // the draw's first rank in the view-depth order

flat out ivec2 vParticle;  // x: the particle's index, y: its rank (one varying: particles.vert says why)
flat out float vFog;

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

void main() {
    int rank = uFirstRank + gl_InstanceID;
    int index = int(drawOrder[rank]);
    vec4 pr = particles[index].positionRadius;
    float depth = -(frame.viewMatrix * vec4(pr.xyz, 1.0)).z;
    if (depth + pr.w < uSheet.x || depth - pr.w > uSheet.y) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // all four corners at one point outside: nothing drawn
        return;
    }
    vParticle = ivec2(index, rank);
    vFog = fogAtPoint(pr.xyz);
    vec2 corner = kCorners[gl_VertexID];
    Billboard b = billboardOf(pr.xyz, pr.w);
    gl_Position = billboardCornerClip(b, pr.xyz, corner);
}
