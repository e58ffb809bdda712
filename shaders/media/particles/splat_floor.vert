#version 450 core
// The splat floor (media/splat_floor.cpp): every particle's billboard, as the splats draw it.
#include "common/math.glsl"
#include "common/frame.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/billboard.glsl"

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

void main() {
    vec4 pr = particles[gl_InstanceID].positionRadius;
    vec2 corner = kCorners[gl_VertexID];
    Billboard b = billboardOf(pr.xyz, pr.w);
    gl_Position = billboardCornerClip(b, pr.xyz, corner);
}
