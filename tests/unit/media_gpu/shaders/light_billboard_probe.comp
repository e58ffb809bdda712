#version 450 core
// light_billboard_test.cpp's probe: the NDC rectangle a particle's quad covers in a perspective
// light view (media/common/light_billboard.glsl lightBillboardCorner), from its four corners.
layout(local_size_x = 64) in;
#include "media/common/light_billboard.glsl"

layout(location = 0) uniform uint uCount;
layout(location = 1) uniform mat4 uProjection;
layout(std430, binding = 0) readonly buffer Spheres { vec4 spheres[]; };  // view-space centre, radius
layout(std430, binding = 1) writeonly buffer Rects { vec4 rects[]; };     // min x, min y, max x, max y

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCount) return;
    vec4 rect = vec4(1e30, 1e30, -1e30, -1e30);
    for (int v = 0; v < 4; ++v) {
        vec4 clip = lightBillboardCorner(spheres[i].xyz, spheres[i].w, true, uProjection, v);
        vec2 ndc = clip.w > 0.0 ? clip.xy / clip.w : vec2(2.0);
        rect = vec4(min(rect.xy, ndc), max(rect.zw, ndc));
    }
    rects[i] = rect;
}
