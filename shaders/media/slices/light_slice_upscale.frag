#version 450 core
// Light-slice upscale (media/slices/light_slice_upscale_pass.cpp): a texel of the slice array
// from the view's small layer, bilinear with the edge clamped (the pass's sampler), as a linear
// blit of the view's corner of the small array would give it.
#include "media/bindings.glsl"
layout(binding = MEDIA_SMALL_SLICES_UNIT) uniform sampler2DArray uSmall;
layout(location = 2) uniform float uScale;  // small-array uv per slice-array pixel: own / (small side · array side)
layout(location = 3) uniform float uLast;   // the uv of the view's last texel centre in the small array

flat in int vSourceLayer;

layout(location = 0) out vec4 outSlices;

void main() {
    // The view fills the small array's corner: past its last texel centre the sampler's edge clamp
    // would read beyond it, so the clamp is the view's own.
    vec2 uv = min(gl_FragCoord.xy * uScale, vec2(uLast));
    outSlices = texture(uSmall, vec3(uv, float(vSourceLayer)));
}
