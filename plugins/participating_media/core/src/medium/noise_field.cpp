// Built with -ffp-contract=off (plugins/participating_media/core/CMakeLists.txt): every operation
// rounds as its GLSL twin's (shaders/media/common/noise.glsl, `precise`) does. Keep the two in step,
// statement by statement: tests/unit/media_gpu/common/noise_field_test.cpp compares their bits.
#include "nimbus/media/noise_field.h"

#include <algorithm>
#include <cmath>

namespace nimbus::media {
namespace {

// Literals as the shortest decimals of their floats, which GLSL parses to the same bits.
constexpr float kTwoPi = 6.2831855f;
constexpr float kTwoPiHi = 6.28125f;  // kTwoPi = hi + lo, hi with few bits so k·hi is exact
constexpr float kTwoPiLo = 0.0019353072f;
constexpr float kInvTwoPi = 0.15915494f;
constexpr float kPi = 3.1415927f;
constexpr float kHalfPi = 1.5707964f;
constexpr std::uint32_t kOctaveStep = 0x9E3779B9u;  // the golden ratio's bits: octaves hash apart
constexpr float kLimit = 1.0e9f;                   // beyond it, lattice indices would not fit an int

float unitOf(std::uint32_t h) { return static_cast<float>(h >> 8u) * 5.9604645e-8f; }

float lattice(int x, int y, int z, std::uint32_t seed) {
    return unitOf(noiseHash(static_cast<std::uint32_t>(x) ^ noiseHash(static_cast<std::uint32_t>(y) ^ noiseHash(static_cast<std::uint32_t>(z) ^ seed))));
}

float lerp(float a, float b, float t) {
    const float d = b - a;
    const float s = d * t;
    return a + s;
}

float fade(float f) {
    float t = f * 6.0f;
    t = t - 15.0f;
    t = t * f;
    t = t + 10.0f;
    float w = f * f;
    w = w * f;
    return w * t;
}

constexpr float kLowestCell = -2147483648.0f, kHighestCell = 2147483520.0f;  // -2^31, the float below 2^31 less 1

float valueNoise(glm::vec3 p, std::uint32_t seed) {
    const glm::vec3 i(std::floor(p.x), std::floor(p.y), std::floor(p.z));
    const glm::vec3 f(p.x - i.x, p.y - i.y, p.z - i.z);
    // The cell as an int, its float clamped into int's range first (the conversion is undefined
    // beyond it, and x + 1 must not overflow): noise.glsl clamps alike, so the bits still agree.
    const auto cell = [](float v) { return static_cast<int>(std::clamp(v, kLowestCell, kHighestCell)); };
    const int x = cell(i.x), y = cell(i.y), z = cell(i.z);
    const glm::vec3 u(fade(f.x), fade(f.y), fade(f.z));
    const float v00 = lerp(lattice(x, y, z, seed), lattice(x + 1, y, z, seed), u.x);
    const float v10 = lerp(lattice(x, y + 1, z, seed), lattice(x + 1, y + 1, z, seed), u.x);
    const float v01 = lerp(lattice(x, y, z + 1, seed), lattice(x + 1, y, z + 1, seed), u.x);
    const float v11 = lerp(lattice(x, y + 1, z + 1, seed), lattice(x + 1, y + 1, z + 1, seed), u.x);
    const float v0 = lerp(v00, v10, u.y);
    const float v1 = lerp(v01, v11, u.y);
    return lerp(v0, v1, u.z);
}

float fractalValue(const NoiseParams& params, glm::vec3 p) {
    float sum = 0.0f, amplitude = 1.0f;
    for (std::uint32_t o = 0; o < params.octaves; ++o) {
        const float v = valueNoise(p, params.seed + o * kOctaveStep);
        const float term = amplitude * v;
        sum = sum + term;
        amplitude = amplitude * params.gain;
        p = glm::vec3(p.x * 2.0f, p.y * 2.0f, p.z * 2.0f);
    }
    return sum * params.invAmplitude;
}

// Gardner's sums of sines in 3D: axis a's octave i has frequency 2ⁱ ω m_a (m_a ∈ [1, 1.5) from the
// seed, so the axes do not repeat together) and phase π/2 · sin of the next axis's octave i − 1
// (the seed's phase θ_a at i = 0).
float sines(const NoiseParams& params, glm::vec3 p) {
    float frequency[3], phase[3], sum[3] = {0.0f, 0.0f, 0.0f}, previous[3];
    for (int a = 0; a < 3; ++a) {
        const std::uint32_t h = noiseHash(params.seed ^ noiseHash(static_cast<std::uint32_t>(a) + 1u));
        const float m = unitOf(h) * 0.5f;
        frequency[a] = kTwoPi * (1.0f + m);
        phase[a] = kTwoPi * unitOf(noiseHash(h));
    }
    float c = 1.0f;
    for (std::uint32_t i = 0; i < params.octaves; ++i) {
        for (int a = 0; a < 3; ++a) {
            const float x = frequency[a] * p[a];
            const float arg = i == 0 ? x + phase[a] : x + kHalfPi * previous[(a + 1) % 3];
            const float s = noiseSin(arg) + 1.0f;
            const float term = c * s;
            sum[a] = sum[a] + term;
        }
        for (int a = 0; a < 3; ++a) {
            const float x = frequency[a] * p[a];
            previous[a] = noiseSin(x);
            frequency[a] = frequency[a] * 2.0f;
        }
        c = c * params.gain;
    }
    // Each sum over its range [0, 2 Σ cᵢ] has mean ½ and the product ⅛: four times it, saturated at
    // 1, centres the pattern at ½ as value noise is, leaving the rare peaks flat-topped.
    const float product = sum[0] * sum[1];
    const float all = product * sum[2];
    return std::min(all * params.invAmplitude, 1.0f);
}

}  // namespace

NoiseParams noiseParams(const NoiseField& field, bool ellipsoid) {
    NoiseParams out;
    out.kind = field.kind == NoiseKind::Sines ? 1u : 0u;
    out.octaves = static_cast<std::uint32_t>(std::clamp(field.octaves, 1, kMaxNoiseOctaves));
    out.seed = field.seed;
    out.gain = static_cast<float>(field.gain);
    float total = 0.0f, amplitude = 1.0f;
    for (std::uint32_t o = 0; o < out.octaves; ++o) {
        total = total + amplitude;
        amplitude = amplitude * out.gain;
    }
    out.invAmplitude = out.kind == 1u ? 4.0f / (8.0f * total * total * total) : 1.0f / total;
    out.coverage = static_cast<float>(field.coverage);
    out.invOneMinusCoverage = 1.0f / (1.0f - out.coverage);
    if (field.falloff > 0.0) {
        const double inner = 1.0 - field.falloff;
        out.invFalloff = static_cast<float>(ellipsoid ? 1.0 / (1.0 - inner * inner) : 1.0 / field.falloff);
    }
    return out;
}

std::uint32_t noiseHash(std::uint32_t x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

float noiseSin(float x) {
    // x − 2πk in two steps (k·hi exact for |k| < 2¹⁶), then [−π, π] folded to [−π/2, π/2] where sin is odd and
    // monotonic: an odd degree-11 Taylor polynomial errs below 6e-8 there.
    const float k = std::floor(x * kInvTwoPi + 0.5f);
    float r = x - k * kTwoPiHi;
    r = r - k * kTwoPiLo;
    // Beyond |k| = 2¹⁶ the product k·hi rounds and r leaves [−π, π]: clamped, the result stays
    // in [−1, 1] (the same on the GPU), though no longer sin.
    r = std::clamp(r, -kPi, kPi);
    if (r > kHalfPi) r = kPi - r;
    if (r < -kHalfPi) r = -kPi - r;
    const float r2 = r * r;
    float s = r2 * -2.5052108e-8f;
    s = s + 2.7557319e-6f;
    s = s * r2;
    s = s + -0.0001984127f;
    s = s * r2;
    s = s + 0.008333334f;
    s = s * r2;
    s = s + -0.16666667f;
    s = s * r2;
    s = s * r;
    return r + s;
}

float noisePattern(const NoiseParams& params, glm::vec3 p) {
    p = glm::clamp(p, glm::vec3(-kLimit), glm::vec3(kLimit));
    return params.kind == 1u ? sines(params, p) : fractalValue(params, p);
}

float noiseDensity(const NoiseParams& params, glm::vec3 p, glm::vec3 unit, bool ellipsoid) {
    const float n = noisePattern(params, p);
    float d = std::max(n - params.coverage, 0.0f);
    d = d * params.invOneMinusCoverage;
    if (params.invFalloff > 0.0f) {
        float inside;
        if (ellipsoid) {
            float r2 = unit.x * unit.x;
            r2 = r2 + unit.y * unit.y;
            r2 = r2 + unit.z * unit.z;
            inside = 1.0f - r2;
        } else {
            inside = 1.0f - std::max(std::max(std::abs(unit.x), std::abs(unit.y)), std::abs(unit.z));
        }
        float e = std::clamp(inside * params.invFalloff, 0.0f, 1.0f);
        const float e2 = e * e;
        const float twice = 2.0f * e;
        e = e2 * (3.0f - twice);
        d = d * e;
    }
    return d;
}

}  // namespace nimbus::media
