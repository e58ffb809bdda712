#version 450 core
// Per-particle lighting (media/particle_lighting_pass.cpp): each particle's source along nine camera
// rays through its billboard (the centre, and ±0.5 and ±0.9 of its half size along its right and
// up axes), fitted over the billboard as
//     F(x, y, β) = F0 + gx·x + gy·y + (r2 + r4·β²)·β² + cx·x³ + cy·y³
// (x, y its corner coordinates in [−1, 1], β the ray's impact parameter in radii). F is a vec4:
// rgb the source of everything but the sun, a the sun's transport to the ray's shading point
// (mesh visibility × the medium's transmittance; with MEDIA_MESH_CROSSINGS the transmittance alone
// where a mesh crosses the particle, flagged by a negated sun factor: the fragments then take the
// visibility over their own segment, as a smooth fit would carry light across the mesh). The
// fragments multiply the sun's by its phase
// function at their own ray (g = 0.99 peaks within a few pixels) and evaluate the lamps near them
// themselves (with MEDIA_SPLAT_FLAGS only where flagged; the fit takes the lamps of the others).
// The odd cubic and even quartic terms follow a dense trail's sunward rim, which brightens sharply.
// SPLAT_CONSTANT: the centre ray alone, for particles a few pixels wide (10⁶ of them).
// LIGHTING_EXACT shades each ray as particles.frag shades a pixel; otherwise light is taken at the
// ray's shading point: phase, the mesh shadow map with Bass and Anderson's smooth weighting over the
// particle's depth, and the slices' transmittance integrated over the layer.
// Once per particle or impostor texel: reading the slice crops costs little here (light_transmittance.glsl).
#define MEDIA_SLICE_CROPS
#include "media/bindings.glsl"
layout(local_size_x = 64) in;
#define SEGMENT_SKIPS_LIGHT litPerFragment

#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/light_views.glsl"
#include "media/common/slices.glsl"
#include "media/common/optics.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/particle_light_layout.glsl"
#include "media/common/lighting.glsl"
#include "media/common/billboard.glsl"

layout(std430, binding = MEDIA_DRAW_ORDER_BINDING) readonly buffer DrawOrder { uint drawOrder[]; };
layout(std430, binding = MEDIA_PARTICLE_LIGHT_BINDING) writeonly buffer ParticleLight { vec4 particleLight[]; };  // per rank: particle_light_layout.glsl
layout(location = 0) uniform uint uCount;
#ifdef MEDIA_SPLAT_FLAGS
// Per particle index, the variant the splats draw it with (particle_splat_pass.h SplatFlag): bit 0
// the mesh-crossing variant (the technique's particlesNearMeshes, the only particles this pass may
// flag as crossed), bit 1 the fragment lamps (particlesNearLamps; without it the fit takes them).
layout(std430, binding = MEDIA_SPLAT_FLAGS_BINDING) readonly buffer SplatFlags { uint splatFlags[]; };
const uint SPLAT_NEAR_MESH = 1u, SPLAT_NEAR_LAMP = 2u;
#endif

const float INNER = 0.5, OUTER = 0.9;  // the two rings of samples, in billboard half sizes

float occluderMargin(int sun, vec3 p) {
#ifdef MEDIA_MESH_CROSSINGS
    return meshShadowMargin(sun, p);
#else
    return 1e30;  // read only to flag crossings
#endif
}

// The sun's transport to p: (mesh visibility, the medium's transmittance over the layer, how far p
// lies in front of the shadow map's occluder along the sun).
vec3 sunTransport(vec3 origin, vec3 dir, Chord chord, float radius, float lo, float hi, float u, float tau, GpuParticle particle) {
    int sun = uFragmentSun;
    vec3 p = origin + dir * (chord.tClosest + u);
    vec3 entry = origin + dir * (chord.tClosest + lo);
    float vBar = shadingDepthFraction(tau) * tau;
#ifdef LIGHTING_EXACT
    float visibility = lights[sun].spot.z >= 0.0 ? segmentVisibility(sun, origin, dir, chord, radius, lo, hi, u) : 1.0;
    return vec3(visibility, layerLightTransmittance(sun, entry, p, vBar, tau, particle), occluderMargin(sun, p));
#else
    float atP = mediumOpticalDepth(sun, p);
    float transmittance = vBar > 1e-4 && tau > 1e-4 ? layerTransmittance(mediumOpticalDepth(sun, entry), atP, vBar, tau) : exp(-atP);
    return vec3(mediumMeshVisibility(sun, p, radius / 3.0), transmittance, occluderMargin(sun, p));
#endif
}

// The source along one ray (rgb: all but the fragments' sun and lamps; a: the sun's transport), and
// the sun's parts apart (sunParts: see sunTransport).
vec4 raySource(vec3 origin, vec3 dir, GpuParticle particle, int index, int rank, out vec3 sunParts) {
    sunParts = vec3(1.0, 0.0, 1e30);
    float radius = particle.positionRadius.w;
    Chord chord = chordOf(origin, dir, particle.positionRadius.xyz, radius);
    float u0 = max(0.0, chord.tClosest - chord.halfChord) - chord.tClosest;  // the medium starts at the eye
    float u1 = chord.halfChord;
    if (!(u1 > u0)) return vec4(particle.albedoSigma.rgb * ambientSource(particle.positionRadius.xyz, dir, particle) + particle.emissionG.rgb, 0.0);
    float tau = particle.albedoSigma.w * chordIntegral(chord, radius, u0, u1);
    float u = chordShadingPoint(chord, radius, u0, u1, tau);
    float lo = max(u0, -chord.halfChord);
    if (uFragmentSun >= 0) sunParts = sunTransport(origin, dir, chord, radius, lo, u1, u, tau, particle);
    float sun = sunParts.x * sunParts.y;
#ifdef LIGHTING_EXACT
    LayerOrder layer = LayerOrder(index, rank, 1e30, 1e30);
    return vec4(segmentSource(origin, dir, chord, radius, lo, u1, u, tau, particle, layer), sun);
#else
    vec3 p = origin + dir * (chord.tClosest + u);
    vec3 entry = origin + dir * (chord.tClosest + lo);
    float vBar = shadingDepthFraction(tau) * tau;
    vec3 scattered = ambientSource(p, dir, particle);
    int i = 0;
    if (frame.counts.x > 0) do {  // not for: llvmpipe runs a for loop's body once more, masked
        if (litPerFragment(i)) continue;
        // The light's transmittance over the whole layer, not at one point (lighting.glsl layerTransmittance).
        float atP = mediumOpticalDepth(i, p);
        float transmittance = vBar > 1e-4 && tau > 1e-4 ? layerTransmittance(mediumOpticalDepth(i, entry), atP, vBar, tau) : exp(-atP);
        scattered += scatteredLight(i, p, dir, particle, -1.0, transmittance);
    } while (++i < frame.counts.x);
    return vec4(particle.albedoSigma.rgb * scattered + particle.emissionG.rgb, sun);
#endif
}

vec4 sourceThrough(vec3 point, GpuParticle particle, int index, int rank, out vec3 sunParts) {
    vec3 origin, dir;
    cameraRayThrough(point, origin, dir);
    return raySource(origin, dir, particle, index, rank, sunParts);
}

// A mesh crosses the particle where the nine rays' visibilities differ by more than this and the
// occluder lies within half a radius of one of their shading points along the sun: the fragments
// then take the visibility themselves (splat_source.glsl). A distant mesh's shadow edge stays in
// the fit. Only particles the technique draws with that variant (MeshNear) are flagged.
const float CROSSED_VISIBILITY_SPREAD = 0.1;

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

// β² of the ray through an origin-relative point.
float impactSquared(vec3 point, vec3 centre, float radius) {
    vec3 origin, dir;
    cameraRayThrough(point, origin, dir);
    Chord c = chordOf(origin, dir, centre, radius);
    return c.b2 / (radius * radius);
}

// The fit's coefficients from the centre and two rings of four samples (`inner`/`outer`: +x, −x,
// +y, −y): per axis an odd g·q + c·q³ through both rings' half differences, and an even
// (r2 + r4·β²)·β² through the rings' means.
void fitBillboard(vec4 centre, vec4 inner[4], vec4 outer[4], float innerB2, float outerB2, out vec4 fit[7]) {
    fit[0] = centre;
    const float a = INNER, c = OUTER, det = a * c * c * c - c * a * a * a;
    for (int axis = 0; axis < 2; ++axis) {
        vec4 oddA = 0.5 * (inner[2 * axis] - inner[2 * axis + 1]), oddC = 0.5 * (outer[2 * axis] - outer[2 * axis + 1]);
        fit[1 + axis] = (oddA * c * c * c - oddC * a * a * a) / det;
        fit[5 + axis] = (a * oddC - c * oddA) / det;
    }
    vec4 evenA = 0.25 * (inner[0] + inner[1] + inner[2] + inner[3]) - centre;
    vec4 evenC = 0.25 * (outer[0] + outer[1] + outer[2] + outer[3]) - centre;
    float even = innerB2 * outerB2 * (outerB2 - innerB2);
    fit[3] = abs(even) > 1e-12 ? (evenA * outerB2 * outerB2 - evenC * innerB2 * innerB2) / even : vec4(0.0);
    fit[4] = abs(even) > 1e-12 ? (evenC * innerB2 - evenA * outerB2) / even : vec4(0.0);
}

void main() {
    uint rank = gl_GlobalInvocationID.x;
    if (rank >= uCount) return;
    int index = int(drawOrder[rank]);
    GpuParticle particle = particles[index];
#ifdef MEDIA_SPLAT_FLAGS
    gLampsInFit = (splatFlags[index] & SPLAT_NEAR_LAMP) == 0u;
#endif
    vec3 centre = particle.positionRadius.xyz;
    float radius = particle.positionRadius.w;
    Billboard b = billboardOf(centre, radius);
    vec4 fit[7] = vec4[](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
    vec3 sun0;
    vec4 j0 = sourceThrough(centre, particle, index, int(rank), sun0);
    uint base = PARTICLE_LIGHT_STRIDE * rank;
    vec3 sunFactor = uFragmentSun >= 0 ? particle.albedoSigma.rgb * lights[uFragmentSun].radiance.rgb : vec3(0.0);
    bool crossed = false;
#ifdef SPLAT_CONSTANT
    particleLight[base] = j0;
#else
    if (b.coversScreen) {  // a quad that covers the screen has no billboard coordinates: F0 throughout
        fit[0] = j0;
    } else {
        vec3 axes[4] = vec3[](b.right, -b.right, b.up, -b.up);
        vec4 inner[4], outer[4];
        vec3 sunInner[4], sunOuter[4];
        float lowest = sun0.x, highest = sun0.x, margin = abs(sun0.z);
        for (int k = 0; k < 4; ++k) {
            inner[k] = sourceThrough(centre + axes[k] * INNER, particle, index, int(rank), sunInner[k]);
            outer[k] = sourceThrough(centre + axes[k] * OUTER, particle, index, int(rank), sunOuter[k]);
            lowest = min(lowest, min(sunInner[k].x, sunOuter[k].x));
            highest = max(highest, max(sunInner[k].x, sunOuter[k].x));
            margin = min(margin, min(abs(sunInner[k].z), abs(sunOuter[k].z)));
        }
#ifdef MEDIA_MESH_CROSSINGS
        crossed = (splatFlags[index] & SPLAT_NEAR_MESH) != 0u && highest - lowest > CROSSED_VISIBILITY_SPREAD && margin < 0.5 * radius;
#endif
        if (crossed) {  // fit the transmittance alone
            j0.a = sun0.y;
            for (int k = 0; k < 4; ++k) {
                inner[k].a = sunInner[k].y;
                outer[k].a = sunOuter[k].y;
            }
        }
        fitBillboard(j0, inner, outer, impactSquared(centre + b.right * INNER, centre, radius),
                     impactSquared(centre + b.right * OUTER, centre, radius), fit);
    }
    for (int k = 0; k < 7; ++k) particleLight[base + uint(k)] = fit[k];
#endif
    particleLight[base + SUN_SLOT] = vec4(crossed ? -sunFactor : sunFactor, centreShadingOffset(centre, particle));
}
