#version 450 core
// Fast particles: per fragment the kernel's optical depth along the pixel's ray, clipped at the
// opaque surface (and at the eye with MEDIA_EYE_INSIDE), from the pre-integrated kernel
// table (the sheet-buffer splatting paper); the source from the lighting pass's fit
// (common/splat_source.glsl). Output (α·J, α) blends premultiplied, exactly as particles.frag's does.
// SPLAT_DEPTH_TESTED: a particle clear of meshes, which the depth test alone clips (particle_splat_pass.cpp).
// One particle a composited layer: the lamps' light takes the exact neighbour order (splat_source.glsl).
#define SPLAT_LAMP_ORDER
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "media/common/optics.glsl"
#include "media/common/peak_orders.glsl"
#include "media/common/kernel_table.glsl"
#include "media/common/particle_light_layout.glsl"
#if defined(MEDIA_FRAGMENT_LAMPS) || defined(MEDIA_MESH_CROSSINGS)
#include "common/light_views.glsl"
#include "media/common/mesh_shadow.glsl"
#endif
#ifdef MEDIA_FRAGMENT_LAMPS
#include "media/common/slices.glsl"
#include "media/common/spot_cone.glsl"
#include "media/common/lamp_quadrature.glsl"
#ifdef SPLAT_LAMP_ORDER
#include "media/common/particle_data.glsl"
#include "media/common/lamp_neighbourhood.glsl"
#endif
#endif
#define SPLAT_VARYING in
#include "media/common/splat_varyings.glsl"
#include "media/common/splat_ray.glsl"
#include "media/common/splat_source.glsl"

#ifndef SPLAT_DEPTH_TESTED
layout(binding = MEDIA_SCENE_DEPTH_UNIT) uniform sampler2D uSceneDepth;
#endif
layout(location = 1) uniform vec2 uFullResScale;
layout(location = 13) uniform vec2 uFragOffset;  // the target's first pixel in the viewport (0 but for a rect of edges)

layout(location = 0) out vec4 outColor;

void main() {
    vec2 fragCoord = gl_FragCoord.xy * uFullResScale + uFragOffset;
    SplatRay r = splatRay();
    float radius = vCentreRadius.w, invRadius = 1.0 / radius;
#ifdef SPLAT_DEPTH_TESTED
    // No surface comes within the quad's reach of the centre, so the depth test clipped it whole,
    // and the eye lies in no such sphere: the whole chord.
    float tSurface = 1e30;
    float segment = kernelColumn(r.beta);
#else
    float depth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
    float tSurface = depth * r.perDepth;
    float segment = kernelSegment(r.beta, (tSurface - r.tc) * invRadius);
#ifdef MEDIA_EYE_INSIDE
    segment -= kernelSegment(r.beta, -r.tc * invRadius);
#endif
#endif
    float alpha = oneMinusExpNeg(vSigma * radius * max(segment, 0.0));
    vec3 source = splatSource(r.origin, r.dir, r.tc, r.perp, r.beta, r.beta2, tSurface, alpha);
    outColor = vec4(source * alpha, alpha);
}
