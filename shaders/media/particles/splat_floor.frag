#version 450 core
// The splat floor: the cheapest fragment that still blends into the media target.
layout(location = 0) out vec4 outColor;

void main() { outColor = vec4(0.001, 0.001, 0.001, 0.01); }
