#version 450 core
#include "lib.glsl"
out vec4 c;
void main() { c = vec4(VALUE * helper()); }
