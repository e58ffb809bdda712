// Per-frame camera and environment (gpu/frame_layout.h GpuFrame). Positions are relative to the
// camera (the frame origin), so the eye is at (0, 0, 0) for perspective views.
layout(std140, binding = 0) uniform Frame {
    mat4 viewProjection;
    mat4 viewMatrix;
    mat4 inverseViewProjection;
    vec4 cameraRight;    // w: tan(yfov/2)·aspect, or ortho half width
    vec4 cameraUp;       // w: tan(yfov/2), or ortho half height
    vec4 cameraForward;  // w: 1 orthographic
    vec4 depthParams;    // xy: linearisation, z: near, w: far (0 infinite)
    vec4 viewport;       // width, height, 1/width, 1/height
    vec4 ambient;
    vec4 background;
    ivec4 counts;        // x: lights, y: unused, z: shadow map size, w: PCF radius
    vec4 fogColor;       // rgb: colour, w: kind (0 none, 1 exp, 2 exp2, 3 linear, 4 height)
    vec4 fogParams;      // density, start, end, falloff
    vec4 fogHeight;      // x: frame origin height above the fog's base, y: background distance (1e30: infinite)
} frame;

bool frameOrthographic() { return frame.cameraForward.w > 0.5; }

// Reversed-Z depth-buffer value → view depth (distance along the camera's forward axis).
float linearViewDepth(float d) {
    if (frameOrthographic()) return frame.depthParams.x + (1.0 - d) * (frame.depthParams.y - frame.depthParams.x);
    return d + frame.depthParams.x > 0.0 ? frame.depthParams.y / (d + frame.depthParams.x) : 1e30;
}

// How far along the camera ray `dir` (unit) the surface at linear view depth `viewDepth` lies.
float rayDistanceAtViewDepth(vec3 dir, float viewDepth) {
    return frameOrthographic() ? viewDepth : viewDepth / max(dot(dir, frame.cameraForward.xyz), 1e-6);
}

// The camera ray at a point of normalised device coordinates, relative to the frame origin, its
// direction not normalised (both linear in the NDC; but llvmpipe's clipping breaks noperspective
// interpolation, so splats hand over a point on their quad instead: splat_vertex.glsl).
void cameraRayAtNdc(vec2 ndc, out vec3 origin, out vec3 direction) {
    vec3 right = frame.cameraRight.xyz * (ndc.x * frame.cameraRight.w), up = frame.cameraUp.xyz * (ndc.y * frame.cameraUp.w);
    bool orthographic = frameOrthographic();
    origin = orthographic ? right + up : vec3(0.0);
    direction = orthographic ? frame.cameraForward.xyz : frame.cameraForward.xyz + right + up;
}

// The camera ray through a window position (pixel centre = integer + 0.5): origin and unit direction,
// both relative to the frame origin. Matches the reference renderer exactly.
void cameraRay(vec2 fragCoord, out vec3 origin, out vec3 direction) {
    cameraRayAtNdc(fragCoord * frame.viewport.zw * 2.0 - 1.0, origin, direction);
    if (!frameOrthographic()) direction = normalize(direction);
}
