#version 450 core
// kernel_table_test.cpp's probe: the GLSL closed form of a particle's optical depth between two
// points of a ray (media/common/optics.glsl kernelSpan) at given (β, lo, hi).
layout(local_size_x = 64) in;
#include "common/math.glsl"
#include "media/common/optics.glsl"

layout(location = 0) uniform uint uCount;
layout(std430, binding = 0) readonly buffer Spans { vec4 spans[]; };  // β, lo, hi, unused
layout(std430, binding = 1) writeonly buffer Values { float values[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < uCount) values[i] = kernelSpan(spans[i].x, spans[i].y, spans[i].z);
}
