#version 450 core
// Compose (docs/design.md §3 step 4): a translucent layer (the media target) holds in-scattered radiance
// (premultiplied) in rgb and the view transmittance in a, so final = layer.rgb + layer.a · opaque.
// COMPOSE_LAYER: there is one; COMPOSE_UPSAMPLE: at a reduced resolution, upsampled with depth
// awareness on the way (common/upsample.glsl). COMPOSE_FOG: the opaque image (meshes and background)
// is seen through the scene's fog (common/fog.glsl); the layer was fogged per particle. Output is linear.
layout(binding = 0) uniform sampler2D uOpaque;

layout(location = 0) out vec4 outRadiance;

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

#ifdef COMPOSE_FOG
// The distance z to what the pixel shows: the surface, or the fog's reach for the background.
vec3 fogged(vec3 opaque, ivec2 p) {
    vec3 origin, dir;
    cameraRay(gl_FragCoord.xy, origin, dir);
    float d = texelFetch(uSceneDepth, p, 0).r;
    float depth = linearViewDepth(d);
    float z = d <= 0.0 ? fogBackgroundDistance()
                       : (frameOrthographic() ? depth : depth / max(dot(dir, frame.cameraForward.xyz), 1e-6));
    return fogSeen(opaque, fogFactor(origin, dir, z));
}
#endif

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 opaque = texelFetch(uOpaque, p, 0).rgb;
#ifdef COMPOSE_FOG
    opaque = fogged(opaque, p);
#endif
#if defined(COMPOSE_UPSAMPLE)
    float depth = linearViewDepth(texelFetch(uSceneDepth, p, 0).r);
    vec4 layer = upsampleLayer(uLayer, uDepthUsed, gl_FragCoord.xy, uScale, depth, uThreshold);
    outRadiance = vec4(layer.rgb + layer.a * opaque, 1.0);
#elif defined(COMPOSE_LAYER)
    vec4 layer = texelFetch(uLayer, p, 0);
    outRadiance = vec4(layer.rgb + layer.a * opaque, 1.0);
#else
    outRadiance = vec4(opaque, 1.0);
#endif
}
