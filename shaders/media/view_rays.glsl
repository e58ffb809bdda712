// Rays of a view (the camera or a light view) through a point of its NDC, relative to the frame
// origin. Perspective: from the eye. Orthographic: from the view's z = 0 plane along its axis, so
// the ray parameter equals view depth.
void viewRay(vec2 ndc, mat4 inverseViewProjection, mat4 view, bool perspective, vec3 eye, out vec3 origin, out vec3 dir) {
    vec4 nearPoint = inverseViewProjection * vec4(ndc, 1.0, 1.0);  // reversed Z: 1 is the near plane
    nearPoint /= nearPoint.w;
    if (perspective) {
        origin = eye;
        dir = normalize(nearPoint.xyz - eye);
    } else {
        vec3 axis = -vec3(view[0][2], view[1][2], view[2][2]);  // view −Z in world space
        float depth = -(view * vec4(nearPoint.xyz, 1.0)).z;
        origin = nearPoint.xyz - axis * depth;
        dir = axis;
    }
}
