#version 450 core
// glTF metallic-roughness factors: L = base·L_amb + emissive + Σ_l f(l, v) · E_l · max(0, n·l) ·
// V_shadow · T_l, f the glTF spec's appendix B BRDF (Schlick F, GGX D, separable Smith visibility),
// T_l the media plugin's light transmittance when compiled with MEDIA_LIGHT_TRANSMITTANCE (1 otherwise).
#include "mini_frame.glsl"
#include "mini_lights.glsl"
#include "mini_shadows.glsl"

// ---- media plugin hook ----------------------------------------------------------------------
// The include comes from Nimbus's shaders folder (the ProgramDesc's include path); it declares the
// MediaSliceViews block and the slices sampler at the points below, which mini_host leaves free.
#ifdef MEDIA_LIGHT_TRANSMITTANCE
#define MEDIA_SLICE_VIEWS_BINDING 3
#define MEDIA_SLICES_UNIT 2
#include "media/host/light_transmittance.glsl"
#endif
// ---------------------------------------------------------------------------------------------

in vec3 vPosition;
in vec3 vNormal;

layout(location = 2) uniform vec4 uBaseColor;          // glTF baseColorFactor (linear)
layout(location = 3) uniform vec2 uMetallicRoughness;  // metallicFactor, roughnessFactor
layout(location = 4) uniform vec3 uEmissive;           // emissiveFactor
layout(location = 5) uniform vec4 uViewForward;        // xyz camera forward, w 1 when orthographic

// f(l, v)·(n·l) for n·l = nl > 0; roughness below 0.03 is taken as 0.03.
vec3 miniBrdfCosine(vec3 base, vec3 n, vec3 v, vec3 l, float nl) {
    float metallic = uMetallicRoughness.x;
    float r = max(uMetallicRoughness.y, 0.03);
    float alpha = r * r;
    float a2 = alpha * alpha;
    vec3 diffuse = base * ((1.0 - metallic) * MINI_INV_PI);
    vec3 f0 = mix(vec3(0.04), base, metallic);
    vec3 h = l + v;
    h *= inversesqrt(max(dot(h, h), 1e-24));
    float vh = clamp(dot(v, h), 0.0, 1.0);
    float nh = dot(n, h);
    float nv = abs(dot(n, v));
    float m = 1.0 - vh;
    float m2 = m * m;
    vec3 fresnel = f0 + (1.0 - f0) * (m2 * m2 * m);
    float d = nh * nh * (a2 - 1.0) + 1.0;
    float distribution = nh > 0.0 ? a2 / (3.14159265358979323846 * d * d) : 0.0;
    float visibility = 1.0 / ((nl + sqrt(a2 + (1.0 - a2) * nl * nl)) * (nv + sqrt(a2 + (1.0 - a2) * nv * nv)));
    return ((1.0 - fresnel) * diffuse + fresnel * (distribution * visibility)) * nl;
}

layout(location = 0) out vec4 outRadiance;

void main() {
    vec3 base = uBaseColor.rgb;
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;  // only double-sided materials are seen from behind

    vec3 v = uViewForward.w > 0.5 ? -uViewForward.xyz : -normalize(vPosition);
    vec3 radiance = base * miniFrame.ambient.rgb + uEmissive;
    int i = 0;
    if (miniFrame.counts.x > 0) do {
        vec3 toLight;
        vec3 irradiance = miniIrradiance(i, vPosition, toLight);
        float cosine = dot(n, toLight);
        if (cosine <= 0.0) continue;
        float visibility = miniShadowVisibility(i, vPosition, n);
        if (visibility <= 0.0) continue;
        float transmittance = 1.0;
#ifdef MEDIA_LIGHT_TRANSMITTANCE
        transmittance = mediaTransmittance(i, miniLights[i].position.xyz, vPosition);
#endif
        radiance += miniBrdfCosine(base, n, v, toLight, cosine) * irradiance * (visibility * transmittance);
    } while (++i < miniFrame.counts.x);
    outRadiance = vec4(radiance, 1.0);
}
