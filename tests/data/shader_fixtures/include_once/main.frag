#version 450 core
#include "a.glsl"
#include "b.glsl"
void main() {}
