#version 450 core
// Mixed resolution (media_edge_stencil_pass.cpp): the full-resolution pixels where the depth-aware
// upsampling of the reduced media target meets a texel computed at another depth keep stencil 1 and
// the colour of an empty medium, (0, 0, 0, 1), for the technique to draw over; so do the pixels of
// uWhole (a lamp's peak, MediaTarget::peak); elsewhere this discards, and the stencil and the
// "not drawn" colour stay.
#include "media/bindings.glsl"
#include "common/frame.glsl"
#include "common/upsample.glsl"

layout(binding = MEDIA_SCENE_DEPTH_UNIT) uniform sampler2D uSceneDepth;
layout(binding = MEDIA_DEPTH_USED_UNIT) uniform sampler2D uDepthUsed;
layout(location = 1) uniform vec2 uScale;       // reduced / full resolution per axis
layout(location = 2) uniform float uThreshold;  // relative depth difference that marks an edge
layout(location = 3) uniform vec2 uOffset;      // the target's first pixel in the viewport
layout(location = 4) uniform vec4 uWhole;       // pixels (lower left, upper right corners) marked whatever the depths

layout(location = 0) out vec4 outEmpty;

void main() {
    vec2 fragCoord = gl_FragCoord.xy + uOffset;
    float depth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
    bool whole = all(greaterThanEqual(fragCoord, uWhole.xy)) && all(lessThan(fragCoord, uWhole.zw));
    if (!whole && !upsampleEdge(upsampleTaps(uDepthUsed, fragCoord, uScale, depth, uThreshold))) discard;
    outEmpty = vec4(0.0, 0.0, 0.0, 1.0);
}
