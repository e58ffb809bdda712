// The multiple-scattering model in real time (docs/scene-format.md §2; the judge computes it exactly).
// Single scattering of the lights stays where each pass evaluates it; what the model adds comes
// from a coarse grid over the medium (common/environment_grid.h), per unit albedo:
//     J_add = L_amb ⟨T_env⟩ + φ/4π,
// the environment's unscattered light (its mean transmittance towards the outside) and the
// radiance of light scattered two or more times, diffused on the grid (common/diffusion.h).
// Needs the frame block (frame.ambient).
#ifdef MEDIA_MULTIPLE
layout(std140, binding = MEDIA_SCATTERING_BINDING) uniform MediaScattering {
    vec4 gridMin;        // xyz origin-relative corner of the grid
    vec4 gridInvExtent;  // xyz 1 / its extent
} scattering;
layout(binding = MEDIA_ENVIRONMENT_UNIT) uniform sampler3D uEnvironment;

// J_add at p (origin-relative), per unit albedo.
vec3 multipleSource(vec3 p) {
    vec4 t = texture(uEnvironment, (p - scattering.gridMin.xyz) * scattering.gridInvExtent.xyz);
    return frame.ambient.rgb * t.x + t.yzw;
}
#endif
