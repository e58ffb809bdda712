#version 450 core
// The seam marks (media_seam_marks_pass.cpp): the billboards of the particles a mesh's box
// enters, as the splats draw them, on the reduced media target.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/billboard.glsl"

layout(std430, binding = MEDIA_SEAM_PARTICLES_BINDING) readonly buffer SeamParticles { uint seamParticles[]; };

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

flat out vec4 vCentreRadius;  // origin-relative world

void main() {
    vec4 pr = particles[seamParticles[gl_InstanceID]].positionRadius;
    vCentreRadius = pr;
    vec2 corner = kCorners[gl_VertexID];
    Billboard b = billboardOf(pr.xyz, pr.w);
    gl_Position = billboardCornerClip(b, pr.xyz, corner);
}
