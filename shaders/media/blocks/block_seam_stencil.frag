#version 450 core
// The texels where block_composite.frag shades a seam run exactly, at least in part (seamWeight > 0),
// as stencil 1 (block_seam_mask_pass.cpp): everywhere else this discards, and the stencil stays 0.
#include "media/bindings.glsl"
#include "media/blocks/block_seam.glsl"

layout(binding = MEDIA_SEAM_MASK_UNIT) uniform sampler2D uSeamMask;
layout(location = 5) uniform int uCell;  // media texels per mask texel, per axis

void main() {
    if (!(seamWeight(uSeamMask, gl_FragCoord.xy, uCell) > 0.0)) discard;
}
