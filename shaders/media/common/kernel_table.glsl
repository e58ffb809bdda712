// Pre-integrated kernel segments (the sheet-buffer splatting paper; media/kernel_table.h): the optical depth of
// a particle of unit radius and unit peak extinction along a ray at impact parameter β, from where the ray
// enters the sphere up to μ past its closest point (β, μ in radii). Bilinear in a small table.
#include "media/bindings.glsl"
layout(binding = MEDIA_KERNEL_TABLE_UNIT) uniform sampler2D uKernelTable;

float kernelSegment(float beta, float mu) {
    vec2 size = vec2(textureSize(uKernelTable, 0));
    vec2 at = vec2(clamp(beta, 0.0, 1.0), clamp(mu, -1.0, 1.0) * 0.5 + 0.5);
    return texture(uKernelTable, (at * (size - 1.0) + 0.5) / size).r;
}
