// Distance fog (scene-format.md §2.1), the GPU twin of assets/fog.h: what is seen at distance z
// along a ray is f·L + (1 − f)·colour. Needs common/frame.glsl (the fog fields of the Frame block).
// Rays start at a frame-relative origin; only its height matters (height fog).

bool fogEnabled() { return frame.fogColor.w > 0.5; }

// ln((1 − e^(−x))/x), stable near 0 (the horizontal ray) and on both sides of it.
float fogLogShape(float x) {
    if (abs(x) < 1e-3) return log(1.0 - x * (0.5 - x / 6.0));
    if (x > 0.0) return log((1.0 - exp(-x)) / x);
    return -x + log((1.0 - exp(x)) / -x);
}

// Height fog's optical depth from a point at `height` above the base, `z` metres along a ray
// rising by `dirY` per metre; evaluated in log space, capped where f is 0 in float anyway.
float heightFogDepth(float height, float dirY, float z) {
    float density = frame.fogParams.x, k = frame.fogParams.w;
    if (!(density > 0.0) || !(z > 0.0)) return 0.0;
    if (k <= 0.0) return density * z;
    float a = k * dirY;
    float logScale = log(density) - k * height;
    float logDepth;
    if (z >= 1e29) {
        if (!(a > 0.0)) return 1e30;
        logDepth = logScale - log(a);
    } else {
        logDepth = logScale + log(z) + fogLogShape(a * z);
    }
    return exp(min(logDepth, 80.0));
}

// f for a ray from `origin` (frame-relative) along unit `dir`, over z metres.
float fogFactor(vec3 origin, vec3 dir, float z) {
    int kind = int(frame.fogColor.w + 0.5);
    float density = frame.fogParams.x;
    z = max(z, 0.0);
    if (kind == 1) return exp(-density * z);
    if (kind == 2) return exp(-(density * z) * (density * z));
    if (kind == 3) return z >= 1e29 ? 0.0 : clamp((frame.fogParams.z - z) / (frame.fogParams.z - frame.fogParams.y), 0.0, 1.0);
    if (kind == 4) return exp(-heightFogDepth(frame.fogHeight.x + origin.y, dir.y, z));
    return 1.0;
}

vec3 fogSeen(vec3 radiance, float f) { return f * radiance + (1.0 - f) * frame.fogColor.rgb; }

// f for what lies at `p` (frame-relative), along the camera ray through it; 1 without fog. The
// media evaluate it once per particle or block in their vertex shaders: llvmpipe would run a
// per-fragment fog branch under a mask even with fog off.
float fogAtPoint(vec3 p) {
    if (!fogEnabled()) return 1.0;
    vec3 forward = frame.cameraForward.xyz;
    if (frameOrthographic()) {
        float z = dot(p, forward);
        return fogFactor(p - forward * z, forward, z);
    }
    float z = length(p);
    return fogFactor(vec3(0.0), z > 0.0 ? p / z : forward, z);
}

// How far rays that hit nothing see fog.
float fogBackgroundDistance() { return frame.fogHeight.y; }
