#version 450 core
// Lambert shading of docs/design.md §4: L_s = baseColor/π · Σ E_l max(0, n·l) V_mesh T_l + baseColor · L_amb.
// V_mesh from the mesh shadow maps (PCF), T_l = exp(−τ) from the medium's light slices when an
// extension provides them (1 otherwise).
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/light_views.glsl"
#include "common/shadows.glsl"
// MEDIA_LIGHT_TRANSMITTANCE: the media plugin's light slices (render::MeshShadingInput).
#ifdef MEDIA_LIGHT_TRANSMITTANCE
#include "media/host/light_transmittance.glsl"
#endif

in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv0;
in vec2 vUv1;

layout(location = 2) uniform vec4 uBaseColorFactor;
layout(location = 3) uniform int uBaseColorTexCoord;  // −1: no texture
layout(binding = 0) uniform sampler2D uBaseColor;

layout(location = 0) out vec4 outRadiance;

void main() {
    vec3 base = uBaseColorFactor.rgb;
    if (uBaseColorTexCoord >= 0) base *= texture(uBaseColor, uBaseColorTexCoord == 0 ? vUv0 : vUv1).rgb;
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;  // only double-sided materials reach here from behind

    vec3 radiance = base * frame.ambient.rgb;
    int i = 0;
    // do-while, not for (here and in the shaders it includes): llvmpipe runs a for loop's body once
    // more under an empty mask, which doubled the cost of a one-light frame.
    if (frame.counts.x > 0) do {
        LightSample s = sampleLight(i, vPosition);
        float cosine = dot(n, s.toLight);
        if (cosine <= 0.0) continue;
        float visibility = meshVisibility(i, vPosition, n);
        if (visibility <= 0.0) continue;
        float transmittance = 1.0;
#ifdef MEDIA_LIGHT_TRANSMITTANCE
        transmittance = mediaTransmittance(i, lights[i].position.xyz, vPosition);
#endif
        radiance += base * INV_PI * s.irradiance * (cosine * visibility * transmittance);
    } while (++i < frame.counts.x);
    outRadiance = vec4(radiance, 1.0);
}
