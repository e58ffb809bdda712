#version 450 core
// light_transmittance_test.cpp's probe: what a lamp's one-plane view gives past its plane at given
// uv across its image (media/host/light_transmittance.glsl), its texels in its layer's first ones.
layout(local_size_x = 64) in;
#include "media/host/light_transmittance.glsl"

layout(location = 0) uniform uint uCount;
layout(std430, binding = 0) readonly buffer Uvs { vec2 uvs[]; };
layout(std430, binding = 1) writeonly buffer Values { float values[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    // Perspective, planes from depth 0 to 1, one slice; read at depth 2, past it: the slice's τ.
    if (i < uCount) values[i] = mediaSliceOpticalDepthAt(vec4(1.0, 0.0, 1.0, 1.0), 0.0, MEDIA_VIEW_EITHER, vec4(uvs[i] * 2.0 - 1.0, 0.0, 1.0), 2.0);
}
