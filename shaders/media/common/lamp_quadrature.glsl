// The quadrature of a point or spot light's in-scattering along one particle's segment of a view
// ray (local_light_segment.glsl for the exact tier, splat_source.glsl for the splats' rays that pass
// near a lamp). Needs common/lights.

const int LAMP_NEAR_NODES = 8;  // in φ around the lamp,
const int LAMP_NODES = 14;      // then three in t on each side beyond it

// The nodes of ∫ f(t)/d(t)² dt over [a, b] = lit for light i, f carrying a kernel centred at ray
// parameter `kernelAt` with radius `radius` (deviation radius/3). Gauss–Legendre in φ with
// t = t_l + b·tan φ (t_l the lamp's closest approach along the ray, b its distance), where 1/d²
// peaks. Where the kernel's centre lies more than two deviations from t_l, its bulk and the
// lamp's peak are integrated apart, split halfway: φ within that reach of t_l, t beyond it, where
// the kernel varies and 1/d² hardly does. φ alone squeezes the far chord into a sliver next to
// ±π/2 with no node in the bulk, and a lamp near a particle's rim glows too bright. b is at least
// 1e-4 of the interval (a lamp exactly on the ray).
struct LampNodes {
    vec2 lit;
    float tLight, b, mid, half_;  // the lamp's closest approach and distance; the φ interval's middle and half width
    float near0, near1;           // the part integrated in φ
    bool split;                   // whether the parts beyond it are integrated in t
};

LampNodes lampNodes(int i, vec3 origin, vec3 dir, vec2 lit, float kernelAt, float radius) {
    LampNodes q;
    q.lit = lit;
    vec3 toLight = lights[i].position.xyz - origin;
    q.tLight = dot(toLight, dir);
    q.b = max(length(toLight - q.tLight * dir), 1e-4 * (lit.y - lit.x));
    float apart = abs(q.tLight - kernelAt);
    float reach = apart > 2.0 * radius / 3.0 ? 0.5 * apart : 1e30;
    q.near0 = clamp(q.tLight - reach, lit.x, lit.y);
    q.near1 = clamp(q.tLight + reach, lit.x, lit.y);
    q.split = q.near1 > q.near0;
    if (!q.split) {
        q.near0 = lit.x;
        q.near1 = lit.y;
    }
    float phi0 = atan((q.near0 - q.tLight) / q.b), phi1 = atan((q.near1 - q.tLight) / q.b);
    q.mid = 0.5 * (phi0 + phi1);
    q.half_ = 0.5 * (phi1 - phi0);
    return q;
}

// Node j (0 ≤ j < LAMP_NODES): its ray parameter and weight (Jacobian and 1/d² included:
// Σ w_j f(t_j) ≈ the integral). The rule's constants are selected, not indexed: the splats' loop
// over the nodes does not unroll, and llvmpipe runs an index that varies by lane lane by lane.
vec2 lampNode(LampNodes q, int j) {
    if (j < LAMP_NEAR_NODES) {
        // Eight-point Gauss–Legendre in φ: nodes ±x_i, i = j / 2.
        int i = j / 2;
        float x = i == 0 ? 0.1834346425 : i == 1 ? 0.5255324099 : i == 2 ? 0.7966664774 : 0.9602898565;
        float w = i == 0 ? 0.3626837834 : i == 1 ? 0.3137066459 : i == 2 ? 0.2223810345 : 0.1012285363;
        return vec2(q.tLight + q.b * tan(q.mid + float(j % 2 == 0 ? -1 : 1) * q.half_ * x), w * q.half_ / q.b);
    }
    // Three-point Gauss–Legendre in t on each far piece, [lit.x, near0] and [near1, lit.y]; zero
    // weights where there is none.
    int k = j - LAMP_NEAR_NODES;
    bool before = k < 3;
    float a = before ? q.lit.x : q.near1, c = before ? q.near0 : q.lit.y;
    float h = q.split && c > a ? 0.5 * (c - a) : 0.0;
    bool middle = k % 3 == 1;
    float t = 0.5 * (a + c) + h * (middle ? 0.0 : k % 3 == 0 ? -0.7745966692 : 0.7745966692);
    float u = t - q.tLight;
    return vec2(t, (middle ? 0.8888888889 : 0.5555555556) * h / (q.b * q.b + u * u));
}

// Every node at once: the ray parameters t[j] and weights w[j]; false when the interval is empty.
bool lampQuadrature(int i, vec3 origin, vec3 dir, vec2 lit, float kernelAt, float radius, out float t[LAMP_NODES],
                    out float w[LAMP_NODES]) {
    LampNodes q = lampNodes(i, origin, dir, lit, kernelAt, radius);
    for (int j = 0; j < LAMP_NODES; ++j) {
        vec2 node = lampNode(q, j);
        t[j] = node.x;
        w[j] = node.y;
    }
    return lit.y > lit.x;
}
