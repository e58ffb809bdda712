#version 450 core
#include "media/bindings.glsl"
#extension GL_ARB_shader_viewport_layer_array : require
// Light-slice deposit (media/light_slice_deposit_pass.cpp): each piece is one particle and one slab
// between two slice planes it reaches; its quad, facing the light and covering the sphere as the
// light sees it, goes to that slab's layer. light_slice_prefix.frag then sums the slabs.
#include "common/math.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/light_billboard.glsl"

layout(std430, binding = MEDIA_SLICE_PIECES_BINDING) readonly buffer SlicePieces { uint slicePieces[]; };  // particle << 5 | slab

layout(location = 0) uniform mat4 uView;        // origin-relative world → light view
layout(location = 2) uniform vec4 uParams;      // y: depth near, z: depth far, w: slices (x: perspective,
                                                // which LIGHT_PERSPECTIVE says: light_slice_deposit.frag)
layout(location = 5) uniform mat4 uProjection;  // light view → light clip
layout(location = 7) uniform int uFirstPiece;   // this view's pieces start there
layout(location = 8) uniform int uFirstLayer;   // this view's first slab layer

flat out vec4 vCentreRadius;  // light view space
flat out vec4 vSlab;          // x, y: the slab's depth range (±1e30 at the ends), z: σ
out vec3 vPoint;              // light view space point of the quad (perspective) or (corner, 0) (orthographic)

void main() {
    uint piece = slicePieces[uFirstPiece + gl_InstanceID];
    int slab = int(piece & 31u);
    gl_Layer = uFirstLayer + slab;
    GpuParticle particle = particles[piece >> 5];
    vec3 c = (uView * vec4(particle.positionRadius.xyz, 1.0)).xyz;
    float radius = particle.positionRadius.w;
    vCentreRadius = vec4(c, radius);
    float spacing = (uParams.z - uParams.y) / uParams.w;
    vSlab = vec4(slab == 0 ? -1e30 : uParams.y + float(slab) * spacing,
                 slab == int(uParams.w) - 1 ? 1e30 : uParams.y + float(slab + 1) * spacing, particle.albedoSigma.w, 0.0);
#ifdef LIGHT_PERSPECTIVE
    gl_Position = lightBillboardCorner(c, radius, true, uProjection, gl_VertexID);
    // The quad's point in view space, for the fragment's ray: clip back to view space.
    vec4 point = inverse(uProjection) * gl_Position;
    vPoint = point.xyz / point.w;
#else
    // Orthographic: only rays within the sphere's section at the slab's face nearest its centre
    // reach into the slab, so the quad shrinks to that disc (most of a particle's pieces lie off its
    // centre; the rays left out would add nothing).
    float off = max(max(vSlab.x + c.z, -c.z - vSlab.y), 0.0);
    float shrink = sqrt(max(1.0 - off * off / (radius * radius), 0.0));
    gl_Position = lightBillboardCorner(c, radius * shrink, false, uProjection, gl_VertexID);
    vPoint = vec3(kLightBillboardCorners[gl_VertexID] * shrink, 0.0);  // in radii: the fragment's β
#endif
}
