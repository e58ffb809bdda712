// The multiple-scattering model in real time (docs/scene-format.md §2; the judge computes it exactly).
// Single scattering of the lights stays where each pass evaluates it; what the model adds comes
// from a coarse grid over the medium (common/environment_grid.h), per unit albedo, towards ω_out:
//     J_add = (L_amb ⟨T_env⟩ + φ/4π) · max(0, 1 + g a·ω_out),
// the environment's unscattered light (its mean transmittance towards the outside) and the
// radiance of light scattered two or more times, diffused on the grid (common/diffusion.h), with
// their P1 anisotropy a: a forward-scattering medium sends the light flowing out of it on.
// Needs the frame block (frame.ambient).
#ifdef MEDIA_MULTIPLE
layout(std140, binding = MEDIA_SCATTERING_BINDING) uniform MediaScattering {
    vec4 gridMin;        // xyz origin-relative corner of the grid
    vec4 gridInvExtent;  // xyz 1 / its extent
} scattering;
layout(binding = MEDIA_ENVIRONMENT_UNIT) uniform sampler3D uEnvironment;
layout(binding = MEDIA_ENVIRONMENT_DIRECTIONAL_UNIT) uniform sampler3D uEnvironmentDirectional;

// J_add at p (origin-relative), per unit albedo, towards the eye along -viewDir, for asymmetry g.
vec3 multipleSource(vec3 p, vec3 viewDir, float g) {
    vec3 uvw = (p - scattering.gridMin.xyz) * scattering.gridInvExtent.xyz;
    vec4 t = texture(uEnvironment, uvw);
    vec3 a = texture(uEnvironmentDirectional, uvw).xyz;
    return (frame.ambient.rgb * t.x + t.yzw) * max(0.0, 1.0 - g * dot(a, viewDir));
}
#endif
