#version 450 core
// A block impostor texel acts as one "super-particle" (seed 000 §2): opacity from its optical depth,
// in-scattering at its optical-depth-weighted shading point with its weighted albedo, emission and
// g. Where the opaque surface lies inside the block's [front, back] interval, the optical depth is
// scaled by the share of its mass in front of it (seed 000 §2.4, with the block's depth profile
// instead of uniform density), so a mesh crossing a cloud shows no billboard plane.
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/light_views.glsl"
#include "common/transmittance.glsl"
#include "media/optics.glsl"
#include "media/particle_data.glsl"
#include "media/lighting.glsl"
#include "media/block_data.glsl"
#include "media/block_lighting.glsl"

layout(binding = 3) uniform sampler2D uSceneDepth;
layout(binding = 5) uniform sampler2D uImpostorDepths;
layout(binding = 6) uniform sampler2D uImpostorSums1;
layout(binding = 7) uniform sampler2D uImpostorSums2;
layout(binding = 8) uniform sampler2D uImpostorMoments;  // τ·mean, τ·(variance + mean²) of the depth along the ray

layout(location = 1) uniform vec2 uFullResScale;  // full-resolution pixels per target texel (offscreen media)

flat in ivec2 vBlock;  // x: the block, y: its rank in the back-to-front order

layout(location = 0) out vec4 outColor;

void main() {
    BlockTile tile = blockTiles[vBlock.x];
    vec2 fragCoord = gl_FragCoord.xy * uFullResScale;  // the full-resolution position this texel stands for
    vec2 ndc = fragCoord * frame.viewport.zw * 2.0 - 1.0;
    ImpostorSample s = readImpostor(uImpostorDepths, uImpostorSums1, uImpostorSums2, uImpostorMoments, 3, tile, tileTexel(tile, ndc));
    if (!(s.tau > 0.0)) discard;
    // An instance of the prototype sits farther or nearer than the prototype the tile was made for.
    s.front += tile.instance.x;
    s.back += tile.instance.x;

    vec3 origin, dir;
    cameraRay(fragCoord, origin, dir);
    float sceneDepth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
    float tSurface = frameOrthographic() ? sceneDepth : sceneDepth / max(dot(dir, frame.cameraForward.xyz), 1e-6);
    if (tSurface <= s.front) discard;  // the block lies wholly behind the surface
    // The share of the block's optical depth in front of the surface, with the depth profile the
    // impostor's moments give (block_lighting.glsl blockProfile).
    vec2 moments = s.sums3.xy / s.tau;
    BlockProfile profile = blockProfile(s.front, s.back, vec2(moments.x + tile.instance.x, moments.y + tile.instance.x * (2.0 * moments.x + tile.instance.x)));
    float tau = s.tau * profileMassBefore(profile, tSurface);
    float alpha = oneMinusExpNeg(tau);
    if (alpha <= 0.0) discard;

    float end = min(s.back, tSurface);
    GpuParticle block;
    block.positionRadius = vec4(tile.centreRadius.xyz, tile.centreRadius.w);
    block.albedoSigma = vec4(s.sums1.yzw / s.tau, 0.0);
    block.emissionG = vec4(s.sums2.xyz / s.tau, clamp(s.sums2.w / s.tau, -0.999, 0.999));
    block.extra = vec4(0.0);
    LayerOrder layer = LayerOrder(-1, vBlock.y, tSurface, 1e30);
    profile.back = max(end, s.front);  // what the light sees of it ends at the surface
    vec3 source = blockSegmentSource(origin, dir, profile, tau, block, layer);
    outColor = vec4(source * alpha, alpha);
}
