#version 450 core
// light_transmittance_test.cpp's probe: what one light view's slices give at given view depths
// (media/host/light_transmittance.glsl mediaSliceOpticalDepthAt), at the array's centre texel.
layout(local_size_x = 64) in;
#include "media/host/light_transmittance.glsl"

layout(location = 0) uniform uint uCount;
layout(location = 1) uniform vec4 uParams;  // the view's params: x perspective, y near, z far, w planes
layout(std430, binding = 0) readonly buffer Depths { float depths[]; };
layout(std430, binding = 1) writeonly buffer Values { float values[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < uCount) values[i] = mediaSliceOpticalDepthAt(uParams, 0.0, MEDIA_VIEW_EITHER, vec4(0.0, 0.0, 0.5, 1.0), depths[i]);
}
