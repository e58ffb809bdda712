// The media plugin's light slices, for a host's mesh shader (docs/integration.md): how much of a
// light reaches an origin-relative point p through the medium, exp(−τ). Slice k (0-based) of a view
// holds the optical depth accumulated from the light up to view depth near + (k+1)(far − near)/K;
// depth `near` has zero. Between slices τ is interpolated linearly, so τ is exact at every plane.
// Layer params2.x + m of the array holds slices 2m − 1, 2m, 2m, 2m + 1 (slice −1: the near plane's
// zero), so one fetch holds both ends of an interval: xy for an even k, zw for an odd one.
#include "common/math.glsl"
#include "common/light_views.glsl"
#include "media/bindings.glsl"

const int MEDIA_MAX_LIGHTS = 64;  // nimbus/media/gpu_bindings.h kMaxHostLights
layout(std140, binding = MEDIA_SLICE_VIEWS_BINDING) uniform MediaSliceViews {
    ivec4 mediaSliceCount;                      // x: slice views this frame (0: none)
    ivec4 mediaLightSlices[MEDIA_MAX_LIGHTS];   // per host light: x first view (−1: none), y view count
    GpuLightView mediaSliceViews[MAX_LIGHT_VIEWS];
};
layout(binding = MEDIA_SLICES_UNIT) uniform sampler2DArray mediaSlices;

// The optical depth one light view's slices hold at a point with clip coordinates `clip` and view
// depth `depth` in that view. Both are linear in the point, so a host may interpolate them per vertex.
float mediaViewOpticalDepthAt(GpuLightView v, vec4 clip, float depth) {
    vec2 uv;
    if (!lightViewClipUv(clip, uv)) return 0.0;  // slices cover the medium: outside them there is none
    int K = int(v.params.w);
    float s = (depth - v.params.y) / (v.params.z - v.params.y) * float(K);
    if (s <= 0.0) return 0.0;
    // The enclosing slices, or the last one past the medium.
    int k = min(int(floor(s)), K - 1);
    vec4 pairs = texture(mediaSlices, vec3(uv, v.params2.x + float(k / 2)));
    vec2 ends = (k & 1) == 0 ? pairs.xy : pairs.zw;
    return s >= float(K) ? ends.y : mix(ends.x, ends.y, s - float(k));
}

// The optical depth one light view's slices hold at p.
float mediaViewOpticalDepth(GpuLightView v, vec3 p) {
    return mediaViewOpticalDepthAt(v, v.viewProjection * vec4(p, 1.0), -(v.view * vec4(p, 1.0)).z);
}

// The view of host light `light` (at origin-relative `lightPosition`) whose slices hold p, or −1.
int mediaLightSliceView(int light, vec3 lightPosition, vec3 p) {
    if (mediaSliceCount.x == 0) return -1;
    ivec4 s = mediaLightSlices[light];
    return s.x < 0 ? -1 : lightViewIndex(s.x, s.y, lightPosition, p);
}

// The view's matrices are its light's first view's (lightViewPoint): a cube face's are not read.
// `count`: the light's slice view count (1, or 6 for a point light), a constant where the caller
// knows it.
float mediaOpticalDepthOf(int light, int count, vec3 lightPosition, vec3 p) {
    int first = mediaLightSlices[light].x;
    if (mediaSliceCount.x == 0 || first < 0) return 0.0;
    int face = lightViewFace(count, lightPosition, p);
    float depth;
    vec4 clip = lightViewPoint(mediaSliceViews[first], count, face, lightPosition, p, depth);
    return mediaViewOpticalDepthAt(mediaSliceViews[first + face], clip, depth);
}

float mediaOpticalDepth(int light, vec3 lightPosition, vec3 p) {
    return mediaOpticalDepthOf(light, mediaLightSlices[light].y, lightPosition, p);
}

float mediaTransmittance(int light, vec3 lightPosition, vec3 p) { return exp(-mediaOpticalDepth(light, lightPosition, p)); }
