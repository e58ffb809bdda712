#version 450 core
// A host's standard depth (0 at the near plane, 1 at the far plane or infinity) re-encoded as the
// plugin reads scene depth: reversed Z for the same camera (frame.glsl linearViewDepth), so every
// media pass takes either host the same way.
#include "media/bindings.glsl"

layout(binding = MEDIA_HOST_DEPTH_UNIT) uniform sampler2D uHostDepth;
layout(location = 0) uniform vec3 uPlanes;     // near, far (0: infinite), 1 orthographic
layout(location = 1) uniform vec2 uReversed;   // gpu::View::depthLinearization(): depth = b / (d + a)

layout(location = 0) out float outDepth;

void main() {
    float d = texelFetch(uHostDepth, ivec2(gl_FragCoord.xy), 0).r;
    float n = uPlanes.x, f = uPlanes.y;
    if (uPlanes.z > 0.5) {  // orthographic: linear in view depth both ways
        outDepth = 1.0 - d;
        return;
    }
    if (d >= 1.0) {  // the far plane or the cleared background
        outDepth = 0.0;
        return;
    }
    // Standard perspective window depth: d = f(z − n) / ((f − n) z), or 1 − n/z without a far plane.
    float z = f > 0.0 ? f * n / (f - d * (f - n)) : n / (1.0 - d);
    outDepth = uReversed.y / z - uReversed.x;
}
