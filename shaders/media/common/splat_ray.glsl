// A splat fragment's camera ray (from the vertices: splat_varyings.glsl) and where it passes the
// particle: particle_splats.frag and sheets/sheet_splats.frag. Needs splat_varyings (as in).
struct SplatRay {
    vec3 origin, dir;
    float perDepth;  // ray distance per unit of view depth, 1/cos θ (1 orthographic)
    float tc;     // the ray's distance to its closest approach to the centre
    vec3 perp;    // the centre's offset from the ray there
    float beta2;  // |perp|² in radii²
    float beta;
};

SplatRay splatRay() {
    SplatRay r;
    r.origin = vRayOrigin;
    float length_ = length(vRayDirection);
    r.dir = vRayDirection / length_;
    r.perDepth = length_ / dot(vRayDirection, frame.cameraForward.xyz);
    vec3 oc = vCentreRadius.xyz - r.origin;
    r.tc = dot(oc, r.dir);
    r.perp = oc - r.tc * r.dir;
    float invRadius = 1.0 / vCentreRadius.w;
    r.beta2 = dot(r.perp, r.perp) * invRadius * invRadius;
    r.beta = sqrt(r.beta2);
    return r;
}
