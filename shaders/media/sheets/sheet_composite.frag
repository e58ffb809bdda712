#version 450 core
// One sheet composited over the sheets behind it (media/sheets/sheet_pass.cpp): the slabs it holds
// as one layer of optical depth τ = Σ τ_i and source Σ τ_i J_i / τ, blended premultiplied as every
// mode's layers are: (α·J, α), α = 1 − e^−τ.
#include "media/bindings.glsl"
#include "common/math.glsl"

layout(binding = MEDIA_SHEET_UNIT) uniform sampler2D uSheet;  // rgb Σ τ_i J_i, a Σ τ_i

layout(location = 0) out vec4 outColor;

void main() {
    vec4 sum = texelFetch(uSheet, ivec2(gl_FragCoord.xy), 0);
    if (!(sum.a > 0.0)) discard;
    float alpha = oneMinusExpNeg(sum.a);
    outColor = vec4(sum.rgb * (alpha / sum.a), alpha);
}
