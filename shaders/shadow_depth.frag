#version 450 core
// Depth comes from the rasteriser; an ALPHA_MASK material cuts its texels away as the opaque pass does.
#include "common/material.glsl"
#ifdef ALPHA_MASK
in float vAlpha;
#ifdef BASE_COLOR_TEXTURE
in vec2 vBaseColorUv;
#endif
#endif

void main() {
#ifdef ALPHA_MASK
    float alpha = vAlpha;
#ifdef BASE_COLOR_TEXTURE
    alpha *= texture(uBaseColor, vBaseColorUv).a;
#endif
    if (alpha < uMaterial.z) discard;
#endif
}
