#version 450 core
#include "common/math.glsl"
void main() {}
