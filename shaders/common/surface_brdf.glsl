// glTF 2.0's metallic-roughness BRDF: the GPU twin of assets/surface_brdf.h (formulas there).
// Needs common/math.glsl.
const float MIN_ROUGHNESS = 0.03;

struct SurfaceBrdf {
    vec3 diffuse;  // c_diff / π
    vec3 f0;
    float alpha2;  // α² = roughness⁴
};

SurfaceBrdf surfaceBrdf(vec3 baseColor, float metallic, float roughness) {
    float r = max(roughness, MIN_ROUGHNESS);
    float alpha = r * r;
    return SurfaceBrdf(baseColor * ((1.0 - metallic) * INV_PI), mix(vec3(0.04), baseColor, metallic), alpha * alpha);
}

// f(l, v) · (n·l) for unit n, v (towards the viewer), l (towards the light), nl = n·l > 0.
vec3 brdfTimesCosine(SurfaceBrdf s, vec3 n, vec3 v, vec3 l, float nl) {
    vec3 h = l + v;
    h *= inversesqrt(max(dot(h, h), 1e-24));
    float vh = clamp(dot(v, h), 0.0, 1.0);
    float nh = dot(n, h);
    float nv = abs(dot(n, v));
    float m = 1.0 - vh;
    float m2 = m * m;
    vec3 fresnel = s.f0 + (1.0 - s.f0) * (m2 * m2 * m);
    float a2 = s.alpha2;
    float d = nh * nh * (a2 - 1.0) + 1.0;
    float distribution = nh > 0.0 ? a2 / (PI * d * d) : 0.0;
    float visibility = 1.0 / ((nl + sqrt(a2 + (1.0 - a2) * nl * nl)) * (nv + sqrt(a2 + (1.0 - a2) * nv * nv)));
    return ((1.0 - fresnel) * s.diffuse + fresnel * (distribution * visibility)) * nl;
}
