#version 450 core
// Mesh shadow map pass: depth only, from one light view (render/shadow_pass.cpp).
layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform mat4 uModel;           // object → origin-relative world
layout(location = 1) uniform mat4 uViewProjection;  // origin-relative world → light clip

void main() { gl_Position = uViewProjection * (uModel * vec4(aPosition, 1.0)); }
