// The noise volumes' density field (C++ twin: plugins/participating_media/core/src/medium/noise_field.cpp,
// nimbus/media/noise_field.h). Every float operation is `precise` and in the C++'s order, and the
// literals are the shortest decimals of the same floats, so both give the same bits for the same
// input (tests/unit/media_gpu/common/noise_field_test.cpp). Keep the two in step, statement by statement.
struct NoiseParams {
    uint kind;     // 0 value, 1 sines
    uint octaves;
    uint seed;
    float gain;
    float invAmplitude;
    float coverage;
    float invOneMinusCoverage;
    float invFalloff;  // 0: no fade at the surface
};

uint noiseHash(uint x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

float noiseUnitOf(uint h) { return float(h >> 8u) * 5.9604645e-8; }

float noiseLattice(int x, int y, int z, uint seed) {
    return noiseUnitOf(noiseHash(uint(x) ^ noiseHash(uint(y) ^ noiseHash(uint(z) ^ seed))));
}

float noiseLerp(precise float a, precise float b, precise float t) {
    precise float d = b - a;
    precise float s = d * t;
    precise float r = a + s;
    return r;
}

float noiseFade(precise float f) {
    precise float t = f * 6.0;
    t = t - 15.0;
    t = t * f;
    t = t + 10.0;
    precise float w = f * f;
    w = w * f;
    precise float r = w * t;
    return r;
}

float noiseSin(precise float x) {
    precise float scaled = x * 0.15915494;
    precise float k = floor(scaled + 0.5);
    precise float hiPart = k * 6.28125;
    precise float r = x - hiPart;
    precise float loPart = k * 0.0019353072;
    r = r - loPart;
    r = clamp(r, -3.1415927, 3.1415927);
    if (r > 1.5707964) r = 3.1415927 - r;
    if (r < -1.5707964) r = -3.1415927 - r;
    precise float r2 = r * r;
    precise float s = r2 * -2.5052108e-8;
    s = s + 2.7557319e-6;
    s = s * r2;
    s = s + -0.0001984127;
    s = s * r2;
    s = s + 0.008333334;
    s = s * r2;
    s = s + -0.16666667;
    s = s * r2;
    s = s * r;
    precise float out_ = r + s;
    return out_;
}

float noiseValue(precise vec3 p, uint seed) {
    precise vec3 i = floor(p);
    precise vec3 f = p - i;
    // Clamped into int's range as noise_field.cpp does: the conversion is undefined beyond it.
    precise vec3 cell = clamp(i, vec3(-2147483648.0), vec3(2147483520.0));
    int x = int(cell.x), y = int(cell.y), z = int(cell.z);
    precise vec3 u = vec3(noiseFade(f.x), noiseFade(f.y), noiseFade(f.z));
    precise float v00 = noiseLerp(noiseLattice(x, y, z, seed), noiseLattice(x + 1, y, z, seed), u.x);
    precise float v10 = noiseLerp(noiseLattice(x, y + 1, z, seed), noiseLattice(x + 1, y + 1, z, seed), u.x);
    precise float v01 = noiseLerp(noiseLattice(x, y, z + 1, seed), noiseLattice(x + 1, y, z + 1, seed), u.x);
    precise float v11 = noiseLerp(noiseLattice(x, y + 1, z + 1, seed), noiseLattice(x + 1, y + 1, z + 1, seed), u.x);
    precise float v0 = noiseLerp(v00, v10, u.y);
    precise float v1 = noiseLerp(v01, v11, u.y);
    return noiseLerp(v0, v1, u.z);
}

float noiseFractalValue(NoiseParams params, precise vec3 p) {
    precise float sum = 0.0, amplitude = 1.0;
    uint o = 0u;
    do {  // not for: llvmpipe runs a for loop's body once more, masked (octaves ≥ 1)
        precise float v = noiseValue(p, params.seed + o * 0x9E3779B9u);
        precise float term = amplitude * v;
        sum = sum + term;
        amplitude = amplitude * params.gain;
        p = p * 2.0;
    } while (++o < params.octaves);
    precise float r = sum * params.invAmplitude;
    return r;
}

float noiseSines(NoiseParams params, precise vec3 p) {
    precise vec3 frequency, phase, previous = vec3(0.0), sum = vec3(0.0);
    for (int a = 0; a < 3; ++a) {
        uint h = noiseHash(params.seed ^ noiseHash(uint(a) + 1u));
        precise float m = noiseUnitOf(h) * 0.5;
        precise float onePlus = 1.0 + m;
        frequency[a] = 6.2831855 * onePlus;
        phase[a] = 6.2831855 * noiseUnitOf(noiseHash(h));
    }
    precise float c = 1.0;
    uint i = 0u;
    do {
        for (int a = 0; a < 3; ++a) {
            precise float x = frequency[a] * p[a];
            precise float shifted = 1.5707964 * previous[(a + 1) % 3];
            precise float arg = i == 0u ? x + phase[a] : x + shifted;
            precise float s = noiseSin(arg) + 1.0;
            precise float term = c * s;
            sum[a] = sum[a] + term;
        }
        for (int a = 0; a < 3; ++a) {
            precise float x = frequency[a] * p[a];
            previous[a] = noiseSin(x);
            frequency[a] = frequency[a] * 2.0;
        }
        c = c * params.gain;
    } while (++i < params.octaves);
    precise float product = sum[0] * sum[1];
    precise float all = product * sum[2];
    precise float r = all * params.invAmplitude;
    return min(r, 1.0);
}

float noisePattern(NoiseParams params, vec3 p) {
    p = clamp(p, vec3(-1.0e9), vec3(1.0e9));
    return params.kind == 1u ? noiseSines(params, p) : noiseFractalValue(params, p);
}

float noiseDensity(NoiseParams params, vec3 p, precise vec3 unit, bool ellipsoid) {
    precise float n = noisePattern(params, p);
    precise float d = max(n - params.coverage, 0.0);
    d = d * params.invOneMinusCoverage;
    if (params.invFalloff > 0.0) {
        precise float inside;
        if (ellipsoid) {
            precise float r2 = unit.x * unit.x;
            precise float y2 = unit.y * unit.y;
            r2 = r2 + y2;
            precise float z2 = unit.z * unit.z;
            r2 = r2 + z2;
            inside = 1.0 - r2;
        } else {
            inside = 1.0 - max(max(abs(unit.x), abs(unit.y)), abs(unit.z));
        }
        precise float scaled = inside * params.invFalloff;
        precise float e = clamp(scaled, 0.0, 1.0);
        precise float e2 = e * e;
        precise float twice = 2.0 * e;
        precise float rest = 3.0 - twice;
        e = e2 * rest;
        d = d * e;
    }
    return d;
}
