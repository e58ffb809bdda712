#version 450 core
// Light-slice pairs (media/slices/light_slice_pairs_pass.cpp): sixteen planes of one view, packed
// four to an RGBA32F layer as the slice passes write them, rewritten two to a layer beside their
// predecessors: layer m of the view holds (τ at planes 2m − 1, 2m, 2m, 2m + 1), the first plane's
// predecessor being the near plane's 0. A lookup between two planes
// (media/host/light_transmittance.glsl) then takes both in one fetch.
#include "media/bindings.glsl"
layout(binding = MEDIA_PACKED_SLICES_UNIT) uniform sampler2DArray uPacked;
layout(location = 0) uniform int uFirstLayer;  // the packed layer of this draw's first plane
layout(location = 1) uniform int uFirstPlane;  // that plane's index within the view (a multiple of 16)

layout(location = 0) out vec4 outPairs[8];

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    int last = textureSize(uPacked, 0).z - 1;  // past the view's planes, what is read goes unwritten
    float p[17];  // planes uFirstPlane − 1 ..
    p[0] = uFirstPlane == 0 ? 0.0 : texelFetch(uPacked, ivec3(texel, max(uFirstLayer - 1, 0)), 0).w;
    for (int l = 0; l < 4; ++l) {
        vec4 v = texelFetch(uPacked, ivec3(texel, min(uFirstLayer + l, last)), 0);
        p[4 * l + 1] = v.x;
        p[4 * l + 2] = v.y;
        p[4 * l + 3] = v.z;
        p[4 * l + 4] = v.w;
    }
    for (int j = 0; j < 8; ++j) outPairs[j] = vec4(p[2 * j], p[2 * j + 1], p[2 * j + 1], p[2 * j + 2]);
}
