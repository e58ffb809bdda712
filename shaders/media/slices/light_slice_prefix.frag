#version 450 core
// Light-slice prefix (media/light_slice_prefix_pass.cpp): the optical depth up to each slice plane
// of one light view, as the running sum of its slabs, into 4 slices per RGBA32F layer, as every
// slice pass writes them (light_slice_intervals.frag rewrites them for the readers). A crop's sum
// starts from its seed: the whole view's optical depth at the crop's first plane, interpolated as a
// lookup would (media planning/slice_crop.h), as no particle is drawn into the crop's first slab.
#include "media/bindings.glsl"
layout(binding = MEDIA_SLABS_UNIT) uniform sampler2DArray uSlabs;
// SLICES: the view's slice count, compile-time (light_slice_prefix_pass.cpp): with a constant count
// the loop unrolls and every index into `values` is a constant, where llvmpipe runs a varying one
// lane by lane.
#ifndef SLICES
#error "light_slice_prefix.frag needs SLICES"
#endif
layout(location = 0) uniform int uFirstSlab;
layout(location = 2) uniform int uSeedSlab;       // the whole view's slab at the crop's first plane (−1: no seed)
layout(location = 3) uniform int uSeedFirstSlab;  // the whole view's first slab
layout(location = 4) uniform float uSeedShare;    // the share of slab uSeedSlab before that plane
layout(location = 5) uniform vec4 uSeedUv;        // xy scale, zw offset: this view's uv to the whole view's

layout(location = 0) out vec4 outSlices[8];

float seed(ivec2 texel) {
    vec2 uv = (vec2(texel) + 0.5) / vec2(textureSize(uSlabs, 0).xy) * uSeedUv.xy + uSeedUv.zw;
    float sum = uSeedShare * textureLod(uSlabs, vec3(uv, float(uSeedSlab)), 0.0).r;
    for (int j = uSeedFirstSlab; j < uSeedSlab; ++j) sum += textureLod(uSlabs, vec3(uv, float(j)), 0.0).r;
    return sum;
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 values[8] = vec4[](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
    float sum = uSeedSlab < 0 ? 0.0 : seed(texel);
    for (int k = 0; k < SLICES; ++k) {
        sum += texelFetch(uSlabs, ivec3(texel, uFirstSlab + k), 0).r;
        values[k >> 2][k & 3] = sum;
    }
    for (int a = 0; a < 8; ++a) outSlices[a] = values[a];
}
