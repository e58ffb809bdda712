#version 450 core
// Compose (docs/design.md §3 step 4): a translucent layer (the media target) holds in-scattered radiance
// (premultiplied) in rgb and the view transmittance in a, so final = layer.rgb + layer.a · opaque.
// The opaque pass drew into the output itself, and this pass blends over it (render/compose_pass.cpp:
// src · 1 + dst · src.a, alpha kept), so it never reads the opaque image: on llvmpipe the blend's read
// of the target costs less than a texture fetch. COMPOSE_LAYER: there is a layer; COMPOSE_UPSAMPLE:
// at a reduced resolution, upsampled with depth awareness on the way (common/upsample.glsl);
// COMPOSE_EDGES: with the layer's edges drawn at full resolution, taken where their alpha is ≥ 0.
// COMPOSE_FOG: the opaque image (meshes and background) is seen through the scene's fog
// (common/fog.glsl), f · opaque + (1 − f) · colour, folded into the blend's two terms; the layer was
// fogged per particle. Output is linear.
layout(location = 0) out vec4 outBlend;

#ifdef COMPOSE_LAYER
layout(binding = 1) uniform sampler2D uLayer;
#endif
#if defined(COMPOSE_UPSAMPLE) || defined(COMPOSE_FOG)
#include "common/frame.glsl"
layout(binding = 3) uniform sampler2D uSceneDepth;
#endif
#ifdef COMPOSE_FOG
#include "common/fog.glsl"
#endif
#ifdef COMPOSE_UPSAMPLE
#include "common/upsample.glsl"
layout(binding = 2) uniform sampler2D uDepthUsed;
layout(location = 1) uniform vec2 uScale;       // reduced / full resolution per axis
layout(location = 2) uniform float uThreshold;  // relative depth difference that marks an edge
#endif
#ifdef COMPOSE_EDGES
layout(binding = 4) uniform sampler2D uEdges;
layout(location = 3) uniform ivec2 uEdgeRect;  // the first pixel uEdges covers
#endif

#ifdef COMPOSE_FOG
// f over the distance z to what the pixel shows: the surface, or the fog's reach for the background.
float fogFactorAt(ivec2 p) {
    vec3 origin, dir;
    cameraRay(gl_FragCoord.xy, origin, dir);
    float d = texelFetch(uSceneDepth, p, 0).r;
    float depth = linearViewDepth(d);
    float z = d <= 0.0 ? fogBackgroundDistance()
                       : (frameOrthographic() ? depth : depth / max(dot(dir, frame.cameraForward.xyz), 1e-6));
    return fogFactor(origin, dir, z);
}
#endif

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
#if defined(COMPOSE_UPSAMPLE)
    float depth = linearViewDepth(texelFetch(uSceneDepth, p, 0).r);
    vec4 layer = upsampleLayer(uLayer, uDepthUsed, gl_FragCoord.xy, uScale, depth, uThreshold);
#ifdef COMPOSE_EDGES
    // Drawn only over the edge rect (render/compose_pass.cpp scissors it), so every pixel has a texel.
    vec4 edge = texelFetch(uEdges, p - uEdgeRect.xy, 0);
    if (edge.a >= 0.0) layer = edge;
#endif
#elif defined(COMPOSE_LAYER)
    vec4 layer = texelFetch(uLayer, p, 0);
#else
    vec4 layer = vec4(0.0, 0.0, 0.0, 1.0);
#endif
#ifdef COMPOSE_FOG
    // layer.rgb + layer.a · (f · opaque + (1 − f) · colour)
    float f = fogFactorAt(p);
    outBlend = vec4(layer.rgb + layer.a * ((1.0 - f) * frame.fogColor.rgb), layer.a * f);
#else
    outBlend = layer;
#endif
}
