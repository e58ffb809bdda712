#version 450 core
// Mixed resolution (media_seam_marks_pass.cpp): a reduced texel whose opaque surface lies inside
// this particle's sphere is marked as computed at no pixel's depth (−1 in the depth it used), so
// every pixel that reads it is an edge (upsampleEdge) and is drawn again at full resolution. There
// the kernel is cut at the surface, and the light a mesh changes there, which the texel spreads
// over the pixels around it. A surface the reduced medium all but hides (view transmittance under
// kHidden: an optical depth over 0.7 in front) is left: it changed the band by under 1%.
#include "media/bindings.glsl"
#include "common/frame.glsl"

layout(binding = MEDIA_SCENE_DEPTH_UNIT) uniform sampler2D uSceneDepth;
layout(binding = MEDIA_REDUCED_MEDIA_UNIT) uniform sampler2D uReducedMedia;  // a: the view transmittance
layout(location = 1) uniform vec2 uFullResScale;                              // full-resolution pixels per texel

flat in vec4 vCentreRadius;

layout(location = 0) out float outUsed;

const float kHidden = 0.5;

void main() {
    // The full-resolution pixel the texel was computed at (depth_used.frag).
    vec2 fragCoord = vec2(ivec2(gl_FragCoord.xy * uFullResScale)) + 0.5;
    vec3 origin, dir;
    cameraRay(fragCoord, origin, dir);
    float sceneDepth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
    float tSurface = rayDistanceAtViewDepth(dir, sceneDepth);
    vec3 toCentre = vCentreRadius.xyz - origin;
    float tClosest = dot(toCentre, dir);
    float missSquared = dot(toCentre, toCentre) - tClosest * tClosest;
    float offset = tSurface - tClosest;
    if (!(offset * offset + missSquared < vCentreRadius.w * vCentreRadius.w)) discard;
    if (texelFetch(uReducedMedia, ivec2(gl_FragCoord.xy), 0).a < kHidden) discard;
    outUsed = -1.0;
}
