#version 450 core
// noise_field_test.cpp's probe: the GLSL noise (media/common/noise.glsl) at given points, for the
// test to compare with the C++ bit for bit.
layout(local_size_x = 64) in;
#include "media/common/noise.glsl"

layout(location = 0) uniform uvec4 uNoise;   // kind, octaves, seed, ellipsoid
layout(location = 1) uniform vec4 uNoise1;   // gain, invAmplitude, coverage, invOneMinusCoverage
layout(location = 2) uniform float uInvFalloff;
layout(location = 3) uniform uint uCount;

layout(std430, binding = 0) readonly buffer Points { vec4 points[]; };  // per point: p, then unit
layout(std430, binding = 1) writeonly buffer Values { vec2 values[]; };  // per point: pattern, density

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCount) return;
    NoiseParams params = NoiseParams(uNoise.x, uNoise.y, uNoise.z, uNoise1.x, uNoise1.y, uNoise1.z, uNoise1.w, uInvFalloff);
    vec3 p = points[2u * i].xyz, unit = points[2u * i + 1u].xyz;
    values[i] = vec2(noisePattern(params, p), noiseDensity(params, p, unit, uNoise.w == 1u));
}
