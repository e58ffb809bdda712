#version 450 core
// A host's mesh shader: the plugin's include comes from the built-in shaders.
#include "media/host/light_transmittance.glsl"
out vec4 colour;
void main() { colour = vec4(1.0); }
