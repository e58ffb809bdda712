#version 450 core
// Volume slices (slices/volume_slice_pass.cpp): for the light ray through this texel, every
// volume's optical depth from the light up to each slice plane, σ times the chord's length before
// the plane, exact for a constant volume. Added onto the particles' slices, in any order.
#include "media/bindings.glsl"
#include "media/common/view_rays.glsl"
#include "media/common/volumes.glsl"

layout(location = 0) uniform mat4 uView;
layout(location = 2) uniform vec4 uParams;      // x: perspective, y: depth near, z: depth far, w: slices
layout(location = 3) uniform vec2 uHalfExtent;  // tan of the half angles, or half size in metres (view_rays.glsl)
layout(location = 4) uniform vec2 uViewportSize;
layout(location = 6) uniform vec3 uLightOrigin;  // origin-relative light position (perspective views)
layout(location = 7) uniform int uVolumeCount;

layout(location = 0) out vec4 outSlices[8];

void main() {
    vec2 ndc = gl_FragCoord.xy / uViewportSize * 2.0 - 1.0;
    bool perspective = uParams.x > 0.5;
    vec3 origin, dir;
    viewRay(ndc, uHalfExtent, uView, perspective, uLightOrigin, origin, dir);
    vec3 axis = -vec3(uView[0][2], uView[1][2], uView[2][2]);  // light view −Z in world space
    float cosAxis = perspective ? max(dot(dir, axis), 1e-6) : 1.0;
    int slices = int(uParams.w);
    float spacing = (uParams.z - uParams.y) / uParams.w;
    vec4 values[8] = vec4[](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
    int v = 0;
    do {  // not for: llvmpipe runs a for loop's body once more, masked
        vec2 chord = volumeChord(v, origin, dir);
        // A perspective view's rays start at the light; an orthographic view counts the whole chord,
        // as the particles' slices do.
        if (perspective) chord.x = max(chord.x, 0.0);
        if (chord.y > chord.x) {
            float sigma = volumes[v].medium.x;
            int s = 0;
            do {
                float plane = (uParams.y + float(s + 1) * spacing) / cosAxis;
                values[s / 4][s - 4 * (s / 4)] += sigma * clamp(plane - chord.x, 0.0, chord.y - chord.x);
            } while (++s < slices);
        }
    } while (++v < uVolumeCount);
    for (int a = 0; a < 8; ++a) outSlices[a] = values[a];
}
