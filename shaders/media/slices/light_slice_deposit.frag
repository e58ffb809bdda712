#version 450 core
// Light-slice deposit: the optical depth one particle puts between two slice planes along the light
// ray through this texel, in closed form (optics.glsl kernelSpan), added into the slab's layer.
// Optical depth adds, so the order pieces arrive in cannot change the sum.
// Works in the light's view space, where the light looks down −Z from the origin (perspective) or
// rays run down −Z from z = 0 (orthographic), so view depth is −z.
#include "common/math.glsl"
#include "media/common/optics.glsl"

// LIGHT_PERSPECTIVE: a point or spot light's view, compile-time (light_slice_deposit_pass.cpp):
// llvmpipe runs both sides of a test of the view's kind, on every fragment.

flat in vec4 vCentreRadius;
flat in vec4 vSlab;
in vec3 vPoint;

layout(location = 0) out float outDepth;

void main() {
    float radius = vCentreRadius.w, invRadius = 1.0 / radius;
    vec3 c = vCentreRadius.xyz;
    float beta, lo, hi;
#ifdef LIGHT_PERSPECTIVE
    vec3 dir = normalize(vPoint);
    float tc = dot(c, dir);
    vec3 perp = c - tc * dir;
    beta = sqrt(dot(perp, perp)) * invRadius;
    float cosAxis = max(-dir.z, 1e-6);
    lo = max(vSlab.x / cosAxis, 0.0) - tc;  // the rays start at the light
    hi = vSlab.y / cosAxis - tc;
#else
    beta = length(vPoint.xy);  // vPoint in radii (light_slice_deposit.vert)
    lo = vSlab.x + c.z;        // ray parameter = view depth = −z
    hi = vSlab.y + c.z;
#endif
    float segment = kernelSpan(beta, lo * invRadius, hi * invRadius);
    outDepth = vSlab.z * radius * max(segment, 0.0);
}
