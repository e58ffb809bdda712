#version 450 core
// Per-particle lighting (media/particle_lighting_pass.cpp): the source J of each particle along five
// camera rays through its billboard, the centre and ±SAMPLE_OFFSET along its right and up axes,
// fitted as J0 + gx·x + gy·y + r·β² (x, y the billboard's corner coordinates in [−1, 1], β the
// ray's impact parameter in radii): particle_splats.vert interpolates the linear part, the
// fragments add the radial one. Fragments then only fetch the kernel's opacity.
// LIGHTING_EXACT evaluates each ray as particles.frag shades a pixel (segmentSource); otherwise
// light is taken at the ray's shading point: phase, the mesh shadow map with seed 001's smooth
// weighting over the particle's depth, and the slices' transmittance integrated over the layer.
layout(local_size_x = 64) in;
#define SEGMENT_SKIPS_LIGHT litPerFragment

#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/light_views.glsl"
#include "common/transmittance.glsl"
#include "media/optics.glsl"
#include "media/particle_data.glsl"
#include "media/particle_light_layout.glsl"
#include "media/lighting.glsl"
#include "media/billboard.glsl"

layout(std430, binding = 5) readonly buffer DrawOrder { uint drawOrder[]; };
layout(std430, binding = 10) writeonly buffer ParticleLight { vec4 particleLight[]; };  // per rank: see PARTICLE_LIGHT_STRIDE
layout(location = 0) uniform uint uCount;

const float SAMPLE_OFFSET = 0.5;
const float OUTER_OFFSET = 0.9;

vec3 raySource(vec3 origin, vec3 dir, GpuParticle particle, int index, int rank) {
    float radius = particle.positionRadius.w;
    Chord chord = chordOf(origin, dir, particle.positionRadius.xyz, radius);
    float u0 = max(0.0, chord.tClosest - chord.halfChord) - chord.tClosest;  // the medium starts at the eye
    float u1 = chord.halfChord;
    if (!(u1 > u0)) return particle.albedoSigma.rgb * frame.ambient.rgb + particle.emissionG.rgb;
    float tau = particle.albedoSigma.w * chordIntegral(chord, radius, u0, u1);
    float u = chordShadingPoint(chord, radius, u0, u1, tau);
#ifdef LIGHTING_EXACT
    LayerOrder layer = LayerOrder(index, rank, 1e30, 1e30);
    return segmentSource(origin, dir, chord, radius, max(u0, -chord.halfChord), u1, u, tau, particle, layer);
#else
    vec3 p = origin + dir * (chord.tClosest + u);
    vec3 entry = origin + dir * (chord.tClosest + max(u0, -chord.halfChord));
    float vBar = shadingDepthFraction(tau) * tau;
    vec3 scattered = frame.ambient.rgb;
    int i = 0;
    if (frame.counts.x > 0) do {  // not for: llvmpipe runs a for loop's body once more, masked
        if (litPerFragment(i)) continue;
        // The light's transmittance over the whole layer, not at one point (lighting.glsl layerTransmittance).
        float atP = mediumOpticalDepth(i, p);
        float transmittance = vBar > 1e-4 && tau > 1e-4 ? layerTransmittance(mediumOpticalDepth(i, entry), atP, vBar, tau) : exp(-atP);
        scattered += scatteredLight(i, p, dir, particle, -1.0, transmittance);
    } while (++i < frame.counts.x);
    return particle.albedoSigma.rgb * scattered + particle.emissionG.rgb;
#endif
}

// How far in front of the closest approach along the centre ray the particle's light is seen (the
// shading point, where its optical depth from the entry reaches v̄), for the fragments' lamps.
float centreShadingOffset(vec3 centre, GpuParticle particle) {
    vec3 origin, dir;
    cameraRayThrough(centre, origin, dir);
    float radius = particle.positionRadius.w;
    Chord chord = chordOf(origin, dir, centre, radius);
    float u0 = max(0.0, chord.tClosest - chord.halfChord) - chord.tClosest;
    if (!(chord.halfChord > u0)) return 0.0;
    float tau = particle.albedoSigma.w * chordIntegral(chord, radius, u0, chord.halfChord);
    return -chordShadingPoint(chord, radius, u0, chord.halfChord, tau);
}

vec3 sourceThrough(vec3 point, GpuParticle particle, int index, int rank) {
    vec3 origin, dir;
    cameraRayThrough(point, origin, dir);
    return raySource(origin, dir, particle, index, rank);
}

// β² of the ray through an origin-relative point, the radial coordinate of the splats' fit.
float impactSquared(vec3 point, vec3 centre, float radius) {
    vec3 origin, dir;
    cameraRayThrough(point, origin, dir);
    Chord c = chordOf(origin, dir, centre, radius);
    return c.b2 / (radius * radius);
}

void main() {
    uint rank = gl_GlobalInvocationID.x;
    if (rank >= uCount) return;
    int index = int(drawOrder[rank]);
    GpuParticle particle = particles[index];
    vec3 centre = particle.positionRadius.xyz;
    float radius = particle.positionRadius.w;
    Billboard b = billboardOf(centre, radius);
    vec3 j0 = sourceThrough(centre, particle, index, int(rank));
    float shadingOffset = centreShadingOffset(centre, particle);
    vec3 gx = vec3(0.0), gy = vec3(0.0), radial = vec3(0.0), quartic = vec3(0.0), cubicX = vec3(0.0), cubicY = vec3(0.0);
    if (!b.coversScreen) {  // a quad that covers the screen has no billboard coordinates: J0 throughout
        vec3 dx = b.right * SAMPLE_OFFSET, dy = b.up * SAMPLE_OFFSET;
        vec3 px = sourceThrough(centre + dx, particle, index, int(rank)), mx = sourceThrough(centre - dx, particle, index, int(rank));
        vec3 py = sourceThrough(centre + dy, particle, index, int(rank)), my = sourceThrough(centre - dy, particle, index, int(rank));
        gx = (px - mx) / (2.0 * SAMPLE_OFFSET);
        gy = (py - my) / (2.0 * SAMPLE_OFFSET);
        // The even part: a dense particle's thin rim is lit through less of its own mass than its
        // centre, so J grows towards the silhouette on every side, which no linear field follows.
        float ring = impactSquared(centre + dx, centre, radius);
        if (ring > 1e-6) radial = (0.25 * (px + mx + py + my) - j0) / ring;
        // Outer ring: odd cubic terms per axis and a quartic radial term.
        vec3 ex = b.right * OUTER_OFFSET, ey = b.up * OUTER_OFFSET;
        vec3 opx = sourceThrough(centre + ex, particle, index, int(rank)), omx = sourceThrough(centre - ex, particle, index, int(rank));
        vec3 opy = sourceThrough(centre + ey, particle, index, int(rank)), omy = sourceThrough(centre - ey, particle, index, int(rank));
        float a = SAMPLE_OFFSET, c = OUTER_OFFSET;
        // odd: f(q) = g q + k q³ through (a, oa) and (c, oc)
        vec3 oa_x = 0.5 * (px - mx), oc_x = 0.5 * (opx - omx), oa_y = 0.5 * (py - my), oc_y = 0.5 * (opy - omy);
        float det = a * c * c * c - c * a * a * a;
        gx = (oa_x * c * c * c - oc_x * a * a * a) / det;
        gy = (oa_y * c * c * c - oc_y * a * a * a) / det;
        cubicX = (a * oc_x - c * oa_x) / det;
        cubicY = (a * oc_y - c * oa_y) / det;
        float ring2 = impactSquared(centre + ex, centre, radius);
        float d2 = ring * ring2 * ring2 - ring2 * ring * ring;
        if (abs(d2) > 1e-9) {
            vec3 ea = 0.25 * (px + mx + py + my) - j0, ec = 0.25 * (opx + omx + opy + omy) - j0;
            radial = (ea * ring2 * ring2 - ec * ring * ring) / d2;
            quartic = (ec * ring - ea * ring2) / d2;
        }
    }
    uint base = PARTICLE_LIGHT_STRIDE * rank;
    particleLight[base] = vec4(j0, shadingOffset);
    particleLight[base + 1u] = vec4(gx, 0.0);
    particleLight[base + 2u] = vec4(gy, 0.0);
    particleLight[base + 3u] = vec4(radial, 0.0);
    particleLight[base + 4u] = vec4(quartic, 0.0);
    particleLight[base + 5u] = vec4(cubicX, 0.0);
    particleLight[base + 6u] = vec4(cubicY, 0.0);
    // The lamps the fragments evaluate: what does not vary across the particle, taken at its centre.
    for (int k = 0; k < MAX_FRAGMENT_LAMPS; ++k) {
        int i = uFragmentLamps[k];
        vec3 factor = vec3(0.0);
        if (i >= 0) factor = particle.albedoSigma.rgb * mediumMeshVisibility(i, centre, radius / 3.0);
        particleLight[base + 7u + uint(k)] = vec4(factor, 0.0);
    }
}
