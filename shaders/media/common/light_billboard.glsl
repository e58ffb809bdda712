// The quad a particle covers in a light view (light_slices.vert, light_slice_deposit.vert), in that
// view's space (the light looks down −Z): perpendicular to the light→centre axis and sized to the
// tangent cone for a perspective view, axis-aligned with half size R for an orthographic one.
// Returns the clip position of corner (x, y) ∈ {−1, 1}².
const vec2 kLightBillboardCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

vec4 lightBillboardCorner(vec3 c, float radius, bool perspective, mat4 projection, int vertex) {
    vec2 corner = kLightBillboardCorners[vertex];
    if (!perspective) return projection * vec4(c + vec3(corner * radius, 0.0), 1.0);
    float d = length(c);
    if (-c.z + radius <= 0.0) return vec4(2.0, 2.0, 2.0, 1.0);  // wholly behind the light (another cube face sees it)
    // The light is inside or just at the sphere: cover everything.
    if (d <= radius * 1.001 || -c.z - radius <= 0.0) return vec4(corner, 0.5, 1.0);
    vec3 axis = c / d;
    vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 right = normalize(cross(axis, helper));
    vec3 up = cross(right, axis);
    float half_ = radius * d / sqrt(d * d - radius * radius);
    return projection * vec4(c + (right * corner.x + up * corner.y) * half_, 1.0);
}
