#version 450 core
// Shadow maps (mesh_renderer.cpp): depth only, from one light view.
layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform mat4 uModel;           // object → camera-relative world
layout(location = 1) uniform mat4 uViewProjection;  // camera-relative world → light clip

void main() { gl_Position = uViewProjection * (uModel * vec4(aPosition, 1.0)); }
