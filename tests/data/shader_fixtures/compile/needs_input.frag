#version 450 core
in vec3 vMissing;
out vec4 c;
void main() { c = vec4(vMissing, 1.0); }
