#version 450 core
// kernel_table_test.cpp's probe: the GLSL closed form of a whole chord's column
// (media/common/kernel_table.glsl kernelColumn) at given offsets β.
layout(local_size_x = 64) in;
#include "media/common/kernel_table.glsl"

layout(location = 0) uniform uint uCount;
layout(std430, binding = 0) readonly buffer Betas { float betas[]; };
layout(std430, binding = 1) writeonly buffer Values { float values[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < uCount) values[i] = kernelColumn(betas[i]);
}
