// The quad a particle covers in a light view (light_slices.vert, light_slice_deposit.vert), in that
// view's space (the light looks down −Z): perpendicular to the light→centre axis and sized to the
// tangent cone for a perspective view, axis-aligned with half size R for an orthographic one.
// Returns the clip position of corner (x, y) ∈ {−1, 1}².
const vec2 kLightBillboardCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

// The slopes x/(−z) of the rays from the light that meet the disc of centre (a, z) and radius r
// ahead of the light (z < 0), where the disc reaches behind it: one axis of a sphere's extent in a
// perspective view. Over that part of the disc the extremes lie at a tangent point ahead of the
// light or where the circle crosses the light's plane, where the slope runs to ±∞ (±1e30).
vec2 aheadSlopes(float a, float z, float r) {
    float k = sqrt(max(r * r - z * z, 0.0));
    vec2 range = vec2(a - k <= 0.0 ? -1e30 : 1e30, a + k >= 0.0 ? 1e30 : -1e30);
    range = vec2(min(range.x, range.y), max(range.x, range.y));
    float d2 = a * a + z * z, t2 = d2 - r * r;
    if (t2 > 0.0) {
        float t = sqrt(t2);
        for (int side = -1; side <= 1; side += 2) {
            vec2 p = (t / d2) * (t * vec2(a, z) + float(side) * r * vec2(-z, a));  // a tangent point
            if (p.y < 0.0) {
                float slope = p.x / -p.y;
                range = vec2(min(range.x, slope), max(range.y, slope));
            }
        }
    }
    return range;
}

vec4 lightBillboardCorner(vec3 c, float radius, bool perspective, mat4 projection, int vertex) {
    vec2 corner = kLightBillboardCorners[vertex];
    if (!perspective) return projection * vec4(c + vec3(corner * radius, 0.0), 1.0);
    float d = length(c);
    if (-c.z + radius <= 0.0) return vec4(2.0, 2.0, 2.0, 1.0);  // wholly behind the light (another cube face sees it)
    // The light is inside or just at the sphere: cover everything.
    if (d <= radius * 1.001) return vec4(corner, 0.5, 1.0);
    if (-c.z - radius <= 0.0) {
        // The sphere reaches behind the light: the rectangle of the view its part ahead covers,
        // per axis (a symmetric projection: NDC = slope × its scale), a little wider for rounding.
        vec2 x = aheadSlopes(c.x, c.z, radius) * projection[0][0], y = aheadSlopes(c.y, c.z, radius) * projection[1][1];
        vec4 rect = clamp(vec4(x.x, y.x, x.y, y.y) + vec4(-1e-4, -1e-4, 1e-4, 1e-4) * (1.0 + abs(vec4(x.x, y.x, x.y, y.y))), -1.0, 1.0);
        if (rect.x >= rect.z || rect.y >= rect.w) return vec4(2.0, 2.0, 2.0, 1.0);  // its part ahead misses this view
        return vec4(mix(rect.xy, rect.zw, corner * 0.5 + 0.5), 0.5, 1.0);
    }
    vec3 axis = c / d;
    vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 right = normalize(cross(axis, helper));
    vec3 up = cross(right, axis);
    float half_ = radius * d / sqrt(d * d - radius * radius);
    return projection * vec4(c + (right * corner.x + up * corner.y) * half_, 1.0);
}
