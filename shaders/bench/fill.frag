#version 450 core
// The fill-rate floor (sandbox bench): the cheapest fragment that still blends into the media
// target, to time how fast the GL implementation can cover pixels at all.
layout(location = 0) out vec4 outColor;

void main() { outColor = vec4(0.001, 0.001, 0.001, 0.01); }
