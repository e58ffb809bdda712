#version 450 core
// Light-slice pass (media/light_slice_pass.cpp): each particle becomes a quad, facing the light,
// that covers its sphere as the light sees it. The fragment shader does the exact integral.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/light_billboard.glsl"

layout(location = 0) uniform mat4 uView;            // origin-relative world → light view
layout(location = 2) uniform vec4 uParams;          // x: perspective, y: depth near, z: depth far, w: slices
layout(location = 5) uniform mat4 uProjection;      // light view → light clip

flat out int vParticle;

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
    gl_Position = lightBillboardCorner(c, pr.w, uParams.x > 0.5, uProjection, gl_VertexID);
}
