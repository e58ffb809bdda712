#version 450 core
// `billboards` mode: one sprite fetch (the kernel's column through the sprite's point, from the
// pre-integrated table) and the classic soft-particle fade against the scene depth (Lorach), over
// one particle radius.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "media/common/kernel_table.glsl"

layout(binding = MEDIA_SCENE_DEPTH_UNIT) uniform sampler2D uSceneDepth;
layout(location = 1) uniform vec2 uFullResScale;

in vec2 vCorner;
flat in vec4 vSource;
flat in vec2 vDepthRadius;

layout(location = 0) out vec4 outColor;

void main() {
    float depth = linearViewDepth(texelFetch(uSceneDepth, ivec2(gl_FragCoord.xy * uFullResScale), 0).r);
    float sprite = frameOrthographic() ? vDepthRadius.x : 1.0 / gl_FragCoord.w;  // the sprite's own view depth here
    float fade = clamp((depth - sprite) / vDepthRadius.y, 0.0, 1.0);
    // The corner coordinates reach the silhouette at 1: the sprite's point is β ≈ |corner| radii off-axis.
    float alpha = fade * oneMinusExpNeg(vSource.a * kernelSegment(length(vCorner), 1.0));
    outColor = vec4(vSource.rgb * alpha, alpha);
}
