#version 450 core
// Offscreen media (Jendersie's offscreen particles): the scene depth each reduced-resolution texel used, so the
// upsampler can tell where a texel does not represent the full-resolution pixel
// (media/media_upsample_pass.cpp).
#include "media/bindings.glsl"
#include "common/frame.glsl"

layout(binding = MEDIA_SCENE_DEPTH_UNIT) uniform sampler2D uSceneDepth;
layout(location = 1) uniform vec2 uFullResScale;

layout(location = 0) out float outDepth;

void main() { outDepth = linearViewDepth(texelFetch(uSceneDepth, ivec2(gl_FragCoord.xy * uFullResScale), 0).r); }
