#version 450 core
// Light-slice pass (media/light_slice_pass.cpp): each particle becomes a quad, facing the light,
// that covers its sphere as the light sees it. The fragment shader does the exact integral.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "media/common/particle_data.glsl"

layout(location = 0) uniform mat4 uView;            // origin-relative world → light view
layout(location = 2) uniform vec4 uParams;          // x: perspective, y: depth near, z: depth far, w: slices
layout(location = 5) uniform mat4 uProjection;      // light view → light clip

flat out int vParticle;

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

#ifdef SLICE_PARTICLE_LIST
// Blocks mode: only the particles a lamp's slices take one by one (media/block_slice_pass.cpp).
layout(std430, binding = MEDIA_LAMP_SLICE_PARTICLES_BINDING) readonly buffer LampSliceParticles { uint lampSliceParticles[]; };
int instanceParticle() { return int(lampSliceParticles[gl_InstanceID]); }
#else
int instanceParticle() { return gl_InstanceID; }
#endif

void main() {
    vParticle = instanceParticle();
    vec4 pr = particles[vParticle].positionRadius;
    vec3 c = (uView * vec4(pr.xyz, 1.0)).xyz;  // light view space; the light looks down −Z
    vec2 corner = kCorners[gl_VertexID];
    if (uParams.x < 0.5) {
        gl_Position = uProjection * vec4(c + vec3(corner * pr.w, 0.0), 1.0);
        return;
    }
    float d = length(c);
    if (-c.z + pr.w <= 0.0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // wholly behind the light (another cube face sees it)
        return;
    }
    if (d <= pr.w * 1.001 || -c.z - pr.w <= 0.0) {
        gl_Position = vec4(corner, 0.5, 1.0);  // the light is inside or just at the sphere: cover everything
        return;
    }
    // A quad perpendicular to the light→centre axis, sized to the tangent cone's cross-section.
    vec3 axis = c / d;
    vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 right = normalize(cross(axis, helper));
    vec3 up = cross(right, axis);
    float half_ = pr.w * d / sqrt(d * d - pr.w * pr.w);
    vec3 p = c + (right * corner.x + up * corner.y) * half_;
    gl_Position = uProjection * vec4(p, 1.0);
}
