// The quad a particle is splatted as (particle_splats.vert, particle_lighting.comp): perpendicular
// to the eye→centre axis and sized to the tangent cone, so it covers the sphere's silhouette
// exactly; screen-aligned with half size R for an orthographic camera. Needs common/frame.glsl.
struct Billboard {
    vec3 right;         // world, scaled to the half size: corner (x, y) lies at centre + right·x + up·y
    vec3 up;
    bool coversScreen;  // the eye is in or near the sphere, or it crosses the near plane
};

Billboard billboardOf(vec3 centre, float radius) {
    if (frameOrthographic()) return Billboard(frame.cameraRight.xyz * radius, frame.cameraUp.xyz * radius, false);
    vec3 c = (frame.viewMatrix * vec4(centre, 1.0)).xyz;
    float d = length(c);
    if (d <= radius * 1.001 || -c.z - radius <= frame.depthParams.z * 2.0) return Billboard(vec3(0.0), vec3(0.0), true);
    vec3 axis = c / d;
    vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 right = normalize(cross(axis, helper));
    vec3 up = cross(right, axis);
    float half_ = radius * d / sqrt(d * d - radius * radius);
    mat3 toWorld = transpose(mat3(frame.viewMatrix));  // the view's rotation is orthonormal
    return Billboard(toWorld * (right * half_), toWorld * (up * half_), false);
}

// A billboard corner (x, y in ±1) in clip space: the quad's, or the whole screen's where it covers it.
vec4 billboardCornerClip(Billboard b, vec3 centre, vec2 corner) {
    return b.coversScreen ? vec4(corner, 0.5, 1.0) : frame.viewProjection * vec4(centre + b.right * corner.x + b.up * corner.y, 1.0);
}

// The camera ray through an origin-relative world point.
void cameraRayThrough(vec3 point, out vec3 origin, out vec3 dir) {
    if (frameOrthographic()) {
        dir = frame.cameraForward.xyz;
        origin = point - dir * dot(point, dir);
    } else {
        origin = vec3(0.0);
        float len = length(point);
        dir = len > 0.0 ? point / len : frame.cameraForward.xyz;
    }
}
