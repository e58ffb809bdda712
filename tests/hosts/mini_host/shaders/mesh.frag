#version 450 core
// Lambert: L = base·L_amb + Σ_l base/π · E_l · max(0, n·l) · V_shadow · T_l, with T_l the media
// plugin's light transmittance when compiled with MEDIA_LIGHT_TRANSMITTANCE (1 otherwise).
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

layout(location = 2) uniform vec4 uBaseColor;  // glTF baseColorFactor (linear)

layout(location = 0) out vec4 outRadiance;

void main() {
    vec3 base = uBaseColor.rgb;
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;  // only double-sided materials are seen from behind

    vec3 radiance = base * miniFrame.ambient.rgb;
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
        radiance += base * MINI_INV_PI * irradiance * (cosine * visibility * transmittance);
    } while (++i < miniFrame.counts.x);
    outRadiance = vec4(radiance, 1.0);
}
