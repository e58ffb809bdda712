#version 450 core
// Light-slice intervals (media/slices/light_slice_intervals_pass.cpp): eight intervals between
// planes of one view, from the planes packed four to an RGBA32F layer as the slice passes write them.
// Layer k of the view holds the optical depth at planes k − 1, k, k + 1, k + 2 (plane 0 the near
// plane, whose τ is 0; planes before it 0 too, planes past the last the last's), so a lookup in
// interval k (media/host/light_transmittance.glsl) takes both ends and their neighbours in one fetch.
// A crop's near plane is no plane of the medium (media planning/slice_crop.h): its τ is extended in
// a line from planes 1 and 2, so the cubic's slope at plane 1 is their secant.
#include "media/bindings.glsl"
layout(binding = MEDIA_PACKED_SLICES_UNIT) uniform sampler2DArray uPacked;
layout(location = 0) uniform int uViewLayer;   // the view's first packed layer
layout(location = 1) uniform int uFirstPlane;  // this draw's first interval (a multiple of 8)
layout(location = 2) uniform int uPlanes;      // the view's planes past the near one
layout(location = 3) uniform bool uCrop;       // a seeded crop's: its near plane is not read

layout(location = 0) out vec4 outIntervals[8];

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    // Planes uFirstPlane − 3 .. uFirstPlane + 12: packed layers of slices uFirstPlane − 4 .. + 11.
    int first = uViewLayer + uFirstPlane / 4 - 1, last = uViewLayer + (uPlanes - 1) / 4;
    vec4 held[4];  // held[j >> 2][j & 3]: plane uFirstPlane − 3 + j, where it is one of the view's
    for (int l = 0; l < 4; ++l) held[l] = texelFetch(uPacked, ivec3(texel, clamp(first + l, uViewLayer, last)), 0);
    // Every index is a constant once the loops unroll (llvmpipe runs a varying index lane by lane):
    // the planes past the last are selected, not indexed.
    float lastDepth = 0.0;
    for (int j = 0; j < 16; ++j) lastDepth = uFirstPlane - 3 + j == uPlanes ? held[j >> 2][j & 3] : lastDepth;
    float tau[16];  // plane uFirstPlane − 3 + j
    for (int j = 0; j < 16; ++j) {
        int plane = uFirstPlane - 3 + j;
        tau[j] = plane <= 0 ? 0.0 : plane > uPlanes ? lastDepth : held[j >> 2][j & 3];
    }
    if (uCrop && uFirstPlane == 0) tau[3] = 2.0 * tau[4] - tau[5];
    for (int i = 0; i < 8; ++i) outIntervals[i] = vec4(tau[i + 2], tau[i + 3], tau[i + 4], tau[i + 5]);
}
