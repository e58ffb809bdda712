#version 450 core
// Depth-aware upsampling of the offscreen media (seed 002): bilinear where the reduced-resolution
// texels were computed at this pixel's depth; at depth edges (a texel's depth differs by more than
// the threshold) the texel among the 3×3 around whose depth matches best, so smoke does not bleed
// over the silhouette of a mesh in front of it.
#include "common/frame.glsl"

layout(binding = 0) uniform sampler2D uMediaLow;
layout(binding = 1) uniform sampler2D uDepthLow;
layout(binding = 3) uniform sampler2D uSceneDepth;
layout(location = 0) uniform vec2 uScale;       // reduced / full resolution per axis (0.5, 0.25)
layout(location = 1) uniform float uThreshold;  // relative depth difference that marks an edge

layout(location = 0) out vec4 outMedia;

void main() {
    float depth = linearViewDepth(texelFetch(uSceneDepth, ivec2(gl_FragCoord.xy), 0).r);
    ivec2 lowSize = textureSize(uMediaLow, 0);
    // Texel i of the low target stands for the full-resolution point (i + 0.5)/scale.
    vec2 p = gl_FragCoord.xy * uScale - 0.5;
    ivec2 base = ivec2(floor(p));
    vec2 f = p - vec2(base);
    bool edge = false;
    vec4 bilinear = vec4(0.0);
    for (int j = 0; j < 4; ++j) {
        ivec2 q = clamp(base + ivec2(j & 1, j >> 1), ivec2(0), lowSize - 1);
        float w = ((j & 1) == 1 ? f.x : 1.0 - f.x) * ((j >> 1) == 1 ? f.y : 1.0 - f.y);
        bilinear += w * texelFetch(uMediaLow, q, 0);
        float used = texelFetch(uDepthLow, q, 0).r;
        edge = edge || abs(used - depth) > uThreshold * min(depth, used);
    }
    if (!edge) {
        outMedia = bilinear;
        return;
    }
    ivec2 centre = clamp(ivec2(gl_FragCoord.xy * uScale), ivec2(0), lowSize - 1);
    float best = 3.0e38;
    vec4 chosen = bilinear;
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            ivec2 q = clamp(centre + ivec2(x, y), ivec2(0), lowSize - 1);
            float difference = abs(texelFetch(uDepthLow, q, 0).r - depth);
            if (difference < best) {
                best = difference;
                chosen = texelFetch(uMediaLow, q, 0);
            }
        }
    }
    outMedia = chosen;
}
