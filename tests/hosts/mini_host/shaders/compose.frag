#version 450 core
// Final image = media.rgb + media.a · opaque (the layer holds premultiplied in-scattered radiance
// and the view transmittance), or the opaque colour alone without a media layer. A reduced layer
// is upsampled with the plugin's depth-aware filter (Nimbus's common/upsample.glsl, as its host
// contract asks), from this pixel's view depth; within the layer's edge rect, its full-resolution
// edges are taken where they were drawn (alpha ≥ 0).
#include "common/upsample.glsl"

layout(binding = 0) uniform sampler2D uOpaque;
layout(binding = 1) uniform sampler2D uMedia;
layout(binding = 2) uniform sampler2D uDepthUsed;
layout(binding = 3) uniform sampler2D uSceneDepth;
layout(binding = 4) uniform sampler2D uEdges;
layout(location = 0) uniform int uMediaMode;   // 0 none, 1 full resolution, 2 reduced
layout(location = 1) uniform vec2 uScale;      // layer size / frame size per axis
layout(location = 2) uniform float uThreshold; // relative depth difference the upsampling treats as an edge
layout(location = 3) uniform vec4 uDepth;      // xy: gpu::View::depthLinearization() (standard: near, far), z: 1 orthographic, w: 1 standard
layout(location = 4) uniform ivec4 uEdgeRect;  // the pixels uEdges covers: x, y, width, height

layout(location = 0) out vec4 outRadiance;

// Depth-buffer value → view depth.
float viewDepth(float d) {
    if (uDepth.w > 0.5) {  // standard: near, far (0: infinite)
        float n = uDepth.x, f = uDepth.y;
        if (uDepth.z > 0.5) return n + d * (f - n);
        if (d >= 1.0) return 1e30;
        return f > 0.0 ? f * n / (f - d * (f - n)) : n / (1.0 - d);
    }
    if (uDepth.z > 0.5) return uDepth.x + (1.0 - d) * (uDepth.y - uDepth.x);
    return d + uDepth.x > 0.0 ? uDepth.y / (d + uDepth.x) : 1e30;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 opaque = texelFetch(uOpaque, p, 0).rgb;
    if (uMediaMode == 0) {
        outRadiance = vec4(opaque, 1.0);
        return;
    }
    vec4 layer = uMediaMode == 1 ? texelFetch(uMedia, p, 0)
                                 : upsampleLayer(uMedia, uDepthUsed, gl_FragCoord.xy, uScale, viewDepth(texelFetch(uSceneDepth, p, 0).r), uThreshold);
    ivec2 q = p - uEdgeRect.xy;
    if (uMediaMode == 2 && all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, uEdgeRect.zw))) {
        vec4 edge = texelFetch(uEdges, q, 0);
        if (edge.a >= 0.0) layer = edge;
    }
    outRadiance = vec4(layer.rgb + layer.a * opaque, 1.0);
}
