// The frame's volumes (volume.h; C++ twin: gpu_bindings.h GpuVolume), frame-relative, and where a
// ray crosses one. Needs media/bindings.glsl.
struct GpuVolume {
    mat4 toUnit;  // frame-relative world → the unit cube [−1, 1]³ (box) or the unit sphere (ellipsoid)
    vec4 medium;  // x σ_t (1/m), y shape (0 box, 1 ellipsoid)
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
