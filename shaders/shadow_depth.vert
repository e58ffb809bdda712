#version 450 core
// Mesh shadow map pass: depth only, from one light view (render/shadow_pass.cpp). ALPHA_MASK
// materials pass on what their cutout reads.
#include "common/material.glsl"
layout(location = 0) in vec3 aPosition;
layout(location = 2) in vec2 aUv0;
layout(location = 3) in vec2 aUv1;
layout(location = 4) in vec4 aColor;
layout(location = 0) uniform mat4 uModel;           // object → origin-relative world
layout(location = 1) uniform mat4 uViewProjection;  // origin-relative world → light clip

#ifdef ALPHA_MASK
out float vAlpha;
#ifdef BASE_COLOR_TEXTURE
out vec2 vBaseColorUv;
#endif
#endif

void main() {
#ifdef ALPHA_MASK
    vAlpha = uBaseColorFactor.a;
#ifdef VERTEX_COLOR
    vAlpha *= aColor.a;
#endif
#ifdef BASE_COLOR_TEXTURE
    vBaseColorUv = materialUv(uBaseColorUv, uBaseColorTexCoord, aUv0, aUv1);
#endif
#endif
    gl_Position = uViewProjection * (uModel * vec4(aPosition, 1.0));
}
