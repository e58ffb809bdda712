#version 450 core
// Volume slices (slices/volume_slice_pass.cpp): for the light ray through this texel, every
// volume's optical depth from the light up to each slice plane, added onto the particles' slices.
// A constant volume's is σ times the chord's length before the plane, exactly. VOLUME_NOISE_GRID:
// the noise volumes' comes from their σ_t on the raymarch grid, marched a voxel a step (midpoint
// rule) with the running sum recorded at each plane it passes.
#include "media/bindings.glsl"
#include "media/common/view_rays.glsl"
#include "media/common/volumes.glsl"

layout(location = 0) uniform mat4 uView;
layout(location = 2) uniform vec4 uParams;      // x: perspective, y: depth near, z: depth far, w: slices
layout(location = 3) uniform vec2 uHalfExtent;  // tan of the half angles, or half size in metres (view_rays.glsl)
layout(location = 4) uniform vec2 uViewportSize;
layout(location = 6) uniform vec3 uLightOrigin;  // origin-relative light position (perspective views)
layout(location = 7) uniform int uVolumeCount;
#ifdef VOLUME_NOISE_GRID
layout(binding = MEDIA_NOISE_GRID_UNIT) uniform sampler3D uNoiseGrid;
layout(location = 8) uniform vec3 uGridCorner;
layout(location = 9) uniform vec3 uGridExtent;
layout(location = 10) uniform float uGridVoxel;
#endif

layout(location = 0) out vec4 outSlices[8];

#ifdef VOLUME_NOISE_GRID
// The noise grid's optical depth up to each plane, added into `values`.
void addNoiseGrid(vec3 origin, vec3 dir, bool perspective, float cosAxis, int slices, float spacing, inout vec4 values[8]) {
    vec3 d = mix(dir, vec3(1e-30), lessThan(abs(dir), vec3(1e-30)));
    vec3 t0 = (uGridCorner - origin) / d, t1 = (uGridCorner + uGridExtent - origin) / d;
    vec3 lo = min(t0, t1), hi = max(t0, t1);
    float enter = max(max(lo.x, lo.y), lo.z), exit = min(min(hi.x, hi.y), hi.z);
    if (perspective) enter = max(enter, 0.0);
    if (!(exit > enter)) return;
    int steps = clamp(int(ceil((exit - enter) / uGridVoxel)), 1, 1024);
    float dt = (exit - enter) / float(steps);
    float tau = 0.0;
    int s = 0;
    float plane = (uParams.y + spacing) / cosAxis;
    // Planes before the grid get nothing.
    while (s < slices && plane <= enter) {
        ++s;
        plane = (uParams.y + float(s + 1) * spacing) / cosAxis;
    }
    for (int k = 0; k < steps && s < slices; ++k) {
        float a = enter + float(k) * dt;
        float sigma = texture(uNoiseGrid, (origin + dir * (a + 0.5 * dt) - uGridCorner) / uGridExtent).r;
        // Every plane inside this step takes the part of it before the plane.
        while (s < slices && plane < a + dt) {
            values[s / 4][s - 4 * (s / 4)] += tau + sigma * (plane - a);
            ++s;
            plane = (uParams.y + float(s + 1) * spacing) / cosAxis;
        }
        tau += sigma * dt;
    }
    for (; s < slices; ++s) values[s / 4][s - 4 * (s / 4)] += tau;
}
#endif

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
        vec2 chord = volumes[v].medium.z > 0.5 ? vec2(1.0, 0.0) : volumeChord(v, origin, dir);  // noise: the grid below
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
#ifdef VOLUME_NOISE_GRID
    addNoiseGrid(origin, dir, perspective, cosAxis, slices, spacing, values);
#endif
    for (int a = 0; a < 8; ++a) outSlices[a] = values[a];
}
