// Rays of a view (the camera or a light view) through a point of its NDC, relative to the frame
// origin. Perspective: from the eye. Orthographic: from the view's z = 0 plane along its axis, so
// the ray parameter equals view depth. `halfExtent`: the symmetric projection's tan of the half
// angles (perspective) or half size in metres (orthographic). Built from the view's rotation, not
// by unprojecting a point of the near plane: a light view's near plane lies so close to the light
// that that point's float coordinates turn the ray enough to miss a millimetre particle's core.
void viewRay(vec2 ndc, vec2 halfExtent, mat4 view, bool perspective, vec3 eye, out vec3 origin, out vec3 dir) {
    mat3 toWorld = transpose(mat3(view));  // the view's rotation is orthonormal
    vec2 onPlane = ndc * halfExtent;
    if (perspective) {
        origin = eye;
        dir = normalize(toWorld * vec3(onPlane, -1.0));
    } else {
        origin = toWorld * (vec3(onPlane, 0.0) - view[3].xyz);
        dir = toWorld * vec3(0.0, 0.0, -1.0);
    }
}
