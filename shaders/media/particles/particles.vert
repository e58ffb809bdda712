#version 450 core
// `particles` mode (media/particle_pass.cpp): sorted billboards, back to front. Each quad covers
// its particle's sphere on screen; the fragment shader integrates the kernel along the pixel's ray.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "media/common/particle_data.glsl"

layout(std430, binding = MEDIA_DRAW_ORDER_BINDING) readonly buffer DrawOrder { uint drawOrder[]; };

// x: the particle's index, y: its place in the draw order. One varying, not two: llvmpipe keeps
// setup data per varying per triangle, which a second one would add for every particle.
flat out ivec2 vParticle;
flat out float vFog;

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

void main() {
    int index = int(drawOrder[gl_InstanceID]);
    vParticle = ivec2(index, gl_InstanceID);
    vec4 pr = particles[index].positionRadius;
    vFog = fogAtPoint(pr.xyz);
    vec2 corner = kCorners[gl_VertexID];
    vec3 c = (frame.viewMatrix * vec4(pr.xyz, 1.0)).xyz;
    if (frameOrthographic()) {
        gl_Position = frame.viewProjection * vec4(pr.xyz + (frame.cameraRight.xyz * corner.x + frame.cameraUp.xyz * corner.y) * pr.w, 1.0);
        return;
    }
    float d = length(c);
    if (d <= pr.w * 1.001 || -c.z - pr.w <= frame.depthParams.z * 2.0) {
        // The eye is in or near the sphere, or the sphere crosses the near plane: cover the screen.
        gl_Position = vec4(corner, 0.5, 1.0);
        return;
    }
    // Perpendicular to the eye→centre axis, sized to the tangent cone: covers the silhouette exactly.
    vec3 axis = c / d;
    vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 right = normalize(cross(axis, helper));
    vec3 up = cross(right, axis);
    float half_ = pr.w * d / sqrt(d * d - pr.w * pr.w);
    vec3 p = c + (right * corner.x + up * corner.y) * half_;
    gl_Position = frame.viewProjection * vec4((transpose(mat3(frame.viewMatrix)) * p), 1.0);
}
