#version 450 core
// Opaque meshes (render/opaque_pass.cpp).
#include "common/frame.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv0;
layout(location = 3) in vec2 aUv1;

layout(location = 0) uniform mat4 uModel;         // object → origin-relative world
layout(location = 1) uniform mat3 uNormalMatrix;  // inverse transpose of the model's 3×3

out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv0;
out vec2 vUv1;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vPosition = world.xyz;
    vNormal = uNormalMatrix * aNormal;
    vUv0 = aUv0;
    vUv1 = aUv1;
    gl_Position = frame.viewProjection * world;
}
