#version 450 core
// Opaque meshes (mesh_renderer.cpp): positions and normals to camera-relative world.
#include "mini_frame.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 0) uniform mat4 uModel;         // object → camera-relative world
layout(location = 1) uniform mat3 uNormalMatrix;  // inverse transpose of the model's 3×3

out vec3 vPosition;
out vec3 vNormal;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vPosition = world.xyz;
    vNormal = uNormalMatrix * aNormal;
    gl_Position = miniFrame.viewProjection * world;
}
