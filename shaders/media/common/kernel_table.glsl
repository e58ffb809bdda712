// Pre-integrated kernel segments (the sheet-buffer splatting paper; media/kernel_table.h): the optical depth of
// a particle of unit radius and unit peak extinction along a ray at impact parameter β, from where the ray
// enters the sphere up to μ past its closest point (β, μ in radii). Bilinear in a small table.
#include "media/bindings.glsl"
layout(binding = MEDIA_KERNEL_TABLE_UNIT) uniform sampler2D uKernelTable;

// kernelSegment(beta, 1), the whole chord's column, in closed form: no fetch (the splats the depth
// test clips). With h² = 1 − β², e^(−kβ²)·erf(√k·h) = e^(−kβ²) − P(t)·e^(−k) for erf after
// Abramowitz and Stegun 7.1.26 (|error| ≤ 1.5e-7), so one exp.
float kernelColumn(float beta) {
    const float k = 4.5, sk = 2.1213203435596424;  // optics.glsl's KERNEL_FALLOFF and its root
    float h = sqrt(max(1.0 - beta * beta, 0.0));
    float t = 1.0 / (1.0 + 0.3275911 * sk * h);
    float p = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
    return (1.7724538509055159 / sk) * max(exp(-k * beta * beta) - p * exp(-k), 0.0);
}

float kernelSegment(float beta, float mu) {
    vec2 size = vec2(textureSize(uKernelTable, 0));
    vec2 at = vec2(clamp(beta, 0.0, 1.0), clamp(mu, -1.0, 1.0) * 0.5 + 0.5);
    return texture(uKernelTable, (at * (size - 1.0) + 0.5) / size).r;
}
