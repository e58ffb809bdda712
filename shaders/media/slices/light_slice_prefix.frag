#version 450 core
// Light-slice prefix (media/light_slice_prefix_pass.cpp): the optical depth up to each slice plane
// of one light view, as the running sum of its slabs, into 4 slices per RGBA32F layer, as every
// slice pass writes them (light_slice_pairs.comp rewrites them for the readers).
#include "media/bindings.glsl"
layout(binding = MEDIA_SLABS_UNIT) uniform sampler2DArray uSlabs;
layout(location = 0) uniform int uFirstSlab;
layout(location = 1) uniform int uSlices;

layout(location = 0) out vec4 outSlices[8];

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 values[8] = vec4[](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
    float sum = 0.0;
    int k = 0;
    do {  // not for: llvmpipe runs a for loop's body once more, masked (slices ≥ 4)
        sum += texelFetch(uSlabs, ivec3(texel, uFirstSlab + k), 0).r;
        values[k / 4][k - 4 * (k / 4)] = sum;
    } while (++k < uSlices);
    for (int a = 0; a < 8; ++a) outSlices[a] = values[a];
}
