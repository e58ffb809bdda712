#version 450 core
// One particle's slab in one sheet (the sheet-buffer splatting paper): the kernel's optical depth
// along the pixel's ray between the sheet's planes, clipped at the opaque surface, as the
// difference of two fetches of the pre-integrated kernel table; the source from the lighting
// pass's fit (common/splat_source.glsl). Output (τ·J, τ) is added into the sheet: a sum does not
// depend on the order the particles arrive in, so no order flips as the view turns.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "media/common/optics.glsl"
#include "media/common/peak_orders.glsl"
#include "media/common/kernel_table.glsl"
#include "media/common/particle_light_layout.glsl"
#ifdef MEDIA_FRAGMENT_LAMPS
#include "common/light_views.glsl"
#include "media/common/slices.glsl"
#include "media/common/spot_cone.glsl"
#include "media/common/lamp_quadrature.glsl"
#include "media/common/mesh_shadow.glsl"
#endif
#define SPLAT_VARYING in
#include "media/common/splat_varyings.glsl"
#include "media/common/splat_ray.glsl"
#include "media/common/splat_source.glsl"

layout(binding = MEDIA_SCENE_DEPTH_UNIT) uniform sampler2D uSceneDepth;
layout(location = 1) uniform vec2 uFullResScale;
layout(location = 2) uniform vec2 uSheet;  // the sheet's near and far view depth (m)

layout(location = 0) out vec4 outColor;

void main() {
    vec2 fragCoord = gl_FragCoord.xy * uFullResScale;
    SplatRay r = splatRay();
    vec3 origin = r.origin, dir = r.dir, perp = r.perp;
    float tc = r.tc, beta2 = r.beta2, beta = r.beta;
    float radius = vCentreRadius.w, invRadius = 1.0 / radius;
    float depth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
    // Along the ray, a plane of view depth z lies at t = z / cos θ (orthographic: t = z).
    float perDepth = r.perDepth;
    float tSurface = depth * perDepth;
    float t0 = uSheet.x * perDepth, t1 = min(uSheet.y * perDepth, tSurface);
    if (!(t1 > t0)) discard;  // the mesh lies in front of this sheet here
    float slab = kernelSegment(beta, (t1 - tc) * invRadius) - kernelSegment(beta, (t0 - tc) * invRadius);
    float tau = vSigma * radius * max(slab, 0.0);
    if (!(tau > 0.0)) discard;
    float alpha = 0.0;  // the whole visible segment's opacity: only the lamps' source reads it
#ifdef MEDIA_FRAGMENT_LAMPS
    alpha = oneMinusExpNeg(vSigma * radius * max(kernelSegment(beta, (tSurface - tc) * invRadius) - kernelSegment(beta, -tc * invRadius), 0.0));
#endif
    outColor = vec4(splatSource(origin, dir, tc, perp, beta, beta2, tSurface, alpha) * tau, tau);
}
