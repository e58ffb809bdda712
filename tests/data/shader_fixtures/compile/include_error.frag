#version 450 core
#include "broken_lib.glsl"
out vec4 c;
void main() { c = vec4(helper()); }
