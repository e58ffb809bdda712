// A spot light's cone along a ray (local_light_segment.glsl, particle_splats.frag). Needs
// common/lights.glsl and media/common/optics.glsl (Chord).
// The part [a, b] of [lo, hi] (u from the chord's closest point) inside light i's cone: all of it
// for a point light, b < a when the ray misses the cone. The forward nappe is convex, so the inside
// is one interval, bounded by roots of (w·D)² = cos²θ_o |w|² with w = x − apex.
vec2 spotConeInterval(int i, vec3 origin, vec3 dir, Chord c, float lo, float hi) {
    GpuLight L = lights[i];
    if (int(L.direction.w + 0.5) != 2) return vec2(lo, hi);
    float cosOuter = L.spot.x > 0.0 ? -L.spot.y / L.spot.x : 0.0;
    vec3 D = L.direction.xyz;
    vec3 w0 = origin + dir * c.tClosest - L.position.xyz;
    float dD = dot(dir, D), wD = dot(w0, D), c2 = cosOuter * cosOuter;
    float A = dD * dD - c2, B = wD * dD - c2 * dot(w0, dir), C = wD * wD - c2 * dot(w0, w0);
    float cuts[4] = float[](lo, lo, hi, hi);
    if (abs(A) > 1e-7) {
        float disc = B * B - A * C;
        if (disc > 0.0) {
            // The root pair without cancellation: q = −(B + sign(B)√disc), roots q/A and C/q.
            float q = -(B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
            float r0 = q / A, r1 = abs(q) > 1e-30 ? C / q : r0;
            cuts[1] = clamp(min(r0, r1), lo, hi);
            cuts[2] = clamp(max(r0, r1), lo, hi);
        }
    } else if (abs(B) > 1e-30) {
        cuts[1] = cuts[2] = clamp(-0.5 * C / B, lo, hi);
    }
    float a = hi, b = lo;
    for (int piece = 0; piece < 3; ++piece) {
        if (!(cuts[piece + 1] > cuts[piece])) continue;
        vec3 x = origin + dir * (c.tClosest + 0.5 * (cuts[piece] + cuts[piece + 1])) - L.position.xyz;
        if (dot(x, D) > cosOuter * length(x)) {
            a = min(a, cuts[piece]);
            b = max(b, cuts[piece + 1]);
        }
    }
    return vec2(a, b);
}
