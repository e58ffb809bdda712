// The frame's volumes (volume.h; C++ twin: gpu_bindings.h GpuVolume), frame-relative, where a ray
// crosses one, and a noise volume's density. Needs media/bindings.glsl.
#include "media/common/noise.glsl"

struct GpuVolume {
    mat4 toUnit;       // frame-relative world → the unit cube [−1, 1]³ (box) or the unit sphere (ellipsoid)
    vec4 medium;       // x σ_t (1/m), y shape (0 box, 1 ellipsoid), z 1 with noise
    vec4 albedoG;      // rgb albedo, w g
    vec4 emission;     // rgb emitted radiance per unit optical depth
    uvec4 noise;       // kind, octaves, seed
    vec4 noiseShape;   // gain, invAmplitude, coverage, invOneMinusCoverage
    vec4 noiseScale;   // xyz unit frame → noise space, w invFalloff
    vec4 noiseOffset;  // xyz noise-space offset (the drift)
};

layout(std430, binding = MEDIA_VOLUMES_BINDING) readonly buffer MediaVolumes {
    GpuVolume volumes[];
};

// [enter, exit] of origin + t·dir inside volume v (t in dir's units; enter ≥ exit: a miss). In the
// unit frame an affine map keeps t, so the chord is a slab test or a quadratic there.
vec2 volumeChord(int v, vec3 origin, vec3 dir) {
    vec3 o = (volumes[v].toUnit * vec4(origin, 1.0)).xyz;
    vec3 d = mat3(volumes[v].toUnit) * dir;
    if (volumes[v].medium.y > 0.5) {
        // |o + t d|² = 1 through the closest point, which does not cancel far off the centre.
        float a = max(dot(d, d), 1e-30);
        float tClosest = -dot(o, d) / a;
        vec3 perp = o + tClosest * d;
        float h2 = (1.0 - dot(perp, perp)) / a;
        if (!(h2 > 0.0)) return vec2(1.0, 0.0);
        float h = sqrt(h2);
        return vec2(tClosest - h, tClosest + h);
    }
    // Zero components become tiny ones: ±infinity slabs rather than NaN.
    vec3 dd = mix(d, vec3(1e-30), lessThan(abs(d), vec3(1e-30)));
    vec3 t0 = (-1.0 - o) / dd, t1 = (1.0 - o) / dd;
    vec3 lo = min(t0, t1), hi = max(t0, t1);
    return vec2(max(max(lo.x, lo.y), lo.z), min(min(hi.x, hi.y), hi.z));
}

// Whether the unit-frame point lies inside volume v's shape.
bool volumeInside(int v, vec3 unit) {
    return volumes[v].medium.y > 0.5 ? dot(unit, unit) <= 1.0 : max(max(abs(unit.x), abs(unit.y)), abs(unit.z)) <= 1.0;
}

// Noise volume v's density scale in [0, 1] at a unit-frame point inside it (noise.glsl).
float volumeNoiseDensity(int v, vec3 unit) {
    GpuVolume vol = volumes[v];
    NoiseParams params = NoiseParams(vol.noise.x, vol.noise.y, vol.noise.z, vol.noiseShape.x, vol.noiseShape.y, vol.noiseShape.z,
                                     vol.noiseShape.w, vol.noiseScale.w);
    vec3 p = unit * vol.noiseScale.xyz + vol.noiseOffset.xyz;
    return noiseDensity(params, p, unit, vol.medium.y > 0.5);
}
