// How a block's optical depth along one light ray is spread over depth (Umenhoffer and Szirmay-Kalos §2.2): a normal
// with the block's optical-depth-weighted mean and deviation along the ray (for a lamp: the normal
// cut at the lamp that has them). block_slices.frag writes the slices with it, and
// block_own_optical_depth.glsl recomputes what they hold of a block. Needs media/optics.

// The normal (μ, s) whose part beyond `lo` has the given mean and deviation. The impostor's moments
// are those of the mass on the ray, which starts at lo (a lamp's position); a normal with the same
// moments, cut there, puts too little mass near lo. The cut normal's deviation / (mean − lo)
// depends on α = (lo − μ)/s alone and grows with it (0.17 at α = −6, 0.76 at 0, 0.94 at 3), so α
// is found by bisection.
vec2 normalCutAt(float lo, float mean, float deviation) {
    float above = mean - lo;
    if (!(above > 0.0)) return vec2(mean, deviation);
    float ratio = deviation / above;
    if (ratio <= 0.1667) return vec2(mean, deviation);  // α < −6: the cut holds no mass
    float a0 = -6.0, a1 = 3.0;
    for (int k = 0; k < 20; ++k) {
        float alpha = 0.5 * (a0 + a1), l = inverseMillsRatio(alpha);
        if (sqrt(max(1.0 + alpha * l - l * l, 0.0)) / (l - alpha) < ratio) a0 = alpha;
        else a1 = alpha;
    }
    float alpha = 0.5 * (a0 + a1);
    float s = above / (inverseMillsRatio(alpha) - alpha);
    return vec2(lo - alpha * s, s);
}

struct BlockLightProfile {
    float mean;       // ray distance from the ray's start
    float deviation;  // <= 1e-6: all of it at the mean
    float scale;      // 1 / (deviation √2)
    float behind;     // erf at `lo`: no mass lies in front of it
    float lo;         // the profile holds no mass before lo or beyond hi
    float hi;
};

// `mean` and `deviation` of the block's mass along the ray (ray distance from its start) and its
// impostor's [front, back]; `fromLight`: the ray starts at the light (a perspective view). The
// block's mass lies within [front − reach, back + reach], and a normal fitted to its moments alone
// spreads it beyond, shadowing what lies just in front of the block. The normal is therefore cut at
// the front (and at the light, where the medium starts) with the same moments, and holds
// everything beyond the back.
BlockLightProfile blockLightProfile(float mean, float deviation, float front, float back, float reach, bool fromLight) {
    float lo = front - reach;
    if (fromLight) lo = max(lo, 0.0);
    if (deviation > 1e-6) {
        vec2 cut = normalCutAt(lo, mean, deviation);
        mean = cut.x;
        deviation = cut.y;
    }
    float scale = deviation > 1e-6 ? 1.0 / (deviation * 1.41421356) : 0.0;
    float behind = deviation > 1e-6 ? erfApprox((lo - mean) * scale) : -1.0;
    return BlockLightProfile(mean, deviation, scale, behind, lo, back + reach);
}

// The share of the block's optical depth up to ray distance t.
float blockLightShare(BlockLightProfile p, float t) {
    if (!(p.deviation > 1e-6)) return t >= p.mean ? 1.0 : 0.0;
    if (t <= p.lo) return 0.0;
    if (t >= p.hi) return 1.0;
    return clamp((erfApprox((t - p.mean) * p.scale) - p.behind) / max(1.0 - p.behind, 1e-6), 0.0, 1.0);
}
