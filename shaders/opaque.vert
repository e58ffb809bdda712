#version 450 core
// Opaque meshes (render/opaque_pass.cpp). Texture coordinates are chosen and transformed here,
// per vertex, so fragments only sample.
#include "common/frame.glsl"
#include "common/material.glsl"
// VERTEX_LIGHTS (0–4): the frame's first lights, each with at most one shadow view and one slice
// view (no cube maps), whose light-view coordinates are computed here: they are linear in the
// position, so interpolating them is exact, and fragments skip two matrix products per view. The
// shadow lookup's normal offset too (exact on a flat face): its image in the shadow view.
#if VERTEX_LIGHTS > 0
#include "common/math.glsl"
#include "common/lights.glsl"
#include "common/light_views.glsl"
#include "common/shadow_views.glsl"
out vec4 vShadowClip[VERTEX_LIGHTS];
out vec4 vShadowOffset[VERTEX_LIGHTS];  // the front face's; a back face (double-sided) negates it
#ifdef MEDIA_LIGHT_TRANSMITTANCE
#include "media/host/light_transmittance.glsl"
out vec4 vSliceClip[VERTEX_LIGHTS];
#ifdef MEDIA_SLICE_CROPS
out vec4 vCropClip[VERTEX_LIGHTS];
#endif
out float vSliceDepth[VERTEX_LIGHTS];
#endif
#endif

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv0;
layout(location = 3) in vec2 aUv1;
layout(location = 4) in vec4 aColor;

layout(location = 0) uniform mat4 uModel;         // object → origin-relative world
layout(location = 1) uniform mat3 uNormalMatrix;  // inverse transpose of the model's 3×3

out vec3 vPosition;
out vec3 vNormal;
#ifdef VERTEX_COLOR
out vec4 vColor;
#endif
#ifdef BASE_COLOR_TEXTURE
out vec2 vBaseColorUv;
#endif
#ifdef METALLIC_ROUGHNESS_TEXTURE
out vec2 vMetallicRoughnessUv;
#endif
#ifdef EMISSIVE_TEXTURE
out vec2 vEmissiveUv;
#endif

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vPosition = world.xyz;
    vNormal = uNormalMatrix * aNormal;
#ifdef VERTEX_COLOR
    vColor = aColor;
#endif
#ifdef BASE_COLOR_TEXTURE
    vBaseColorUv = materialUv(uBaseColorUv, uBaseColorTexCoord, aUv0, aUv1);
#endif
#ifdef METALLIC_ROUGHNESS_TEXTURE
    vMetallicRoughnessUv = materialUv(uMetallicRoughnessUv, uMetallicRoughnessTexCoord, aUv0, aUv1);
#endif
#ifdef EMISSIVE_TEXTURE
    vEmissiveUv = materialUv(uEmissiveUv, uEmissiveTexCoord, aUv0, aUv1);
#endif
    gl_Position = frame.viewProjection * world;
#if VERTEX_LIGHTS > 0
    vec4 p = vec4(world.xyz, 1.0);
    for (int i = 0; i < VERTEX_LIGHTS; ++i) {
        GpuLightView shadow = shadowViews[max(int(lights[i].spot.z), 0)];  // unused when the light has none
        vShadowClip[i] = shadow.viewProjection * p;
        vec3 offset = normalize(vNormal) * shadowOffset(shadow, max(-(shadow.view * p).z, 0.0));
        vShadowOffset[i] = shadow.viewProjection * vec4(offset, 0.0);
#ifdef MEDIA_LIGHT_TRANSMITTANCE
        ivec4 sliceViews = mediaLightSlices[i];
        GpuLightView slices = mediaSliceViews[max(sliceViews.x, 0)];
        vSliceClip[i] = slices.viewProjection * p;
        vSliceDepth[i] = -(slices.view * p).z;
#ifdef MEDIA_SLICE_CROPS
        // A crop's clip coordinates (light_transmittance.glsl), or a point outside any crop.
        vCropClip[i] = sliceViews.y == 2 ? mediaCropClip(slices, mediaSliceViews[sliceViews.x + 1], vSliceClip[i]) : vec4(2.0, 2.0, 0.0, 1.0);
#endif
#endif
    }
#endif
}
