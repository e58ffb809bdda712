// The media plugin's light slices, for a host's mesh shader (docs/integration.md): how much of a
// light reaches an origin-relative point p through the medium, exp(−τ). Plane k (k = 1..K) of a
// view lies at view depth near + k(far − near)/K and holds the optical depth accumulated from the
// light up to it; the near plane (k = 0) has zero. Layer params2.x + k of the array holds interval
// k: τ at planes k − 1, k, k + 1, k + 2 (0 before the near plane, the last plane's past it), so one
// fetch holds both ends of the interval and their neighbours. Between planes τ follows a monotone
// cubic through them: exact at every plane, never falling, and far closer than a straight line
// inside a particle, whose τ bends as its kernel's integral (the seam where a mesh cuts it), where
// the planes lie a third of a radius apart or closer.
#include "common/math.glsl"
#include "common/light_views.glsl"
#include "media/bindings.glsl"

const int MEDIA_MAX_LIGHTS = 64;  // nimbus/media/gpu_bindings.h kMaxHostLights
layout(std140, binding = MEDIA_SLICE_VIEWS_BINDING) uniform MediaSliceViews {
    // x: slice views this frame (0: none). A lamp's views may hold fewer texels than the array's
    // side (media SliceView::resolution), in their layers' first ones: y their share of the side,
    // w the largest uv a lookup takes there (float bits; 1 and 1 where every view is whole), z
    // their texels per side (0: the array's).
    ivec4 mediaSliceCount;
    ivec4 mediaLightSlices[MEDIA_MAX_LIGHTS];   // per host light: x first view (−1: none), y view count
    GpuLightView mediaSliceViews[MAX_LIGHT_VIEWS];
};
layout(binding = MEDIA_SLICES_UNIT) uniform sampler2DArray mediaSlices;

// A view's kind for the lookups below: orthographic, perspective (a lamp's), or as its params say.
// A caller that knows passes a constant, and the other way folds away: llvmpipe runs the test and
// the scaling on every lookup, the sun's too (docs/design-notes.md).
const int MEDIA_VIEW_ORTHOGRAPHIC = 0, MEDIA_VIEW_PERSPECTIVE = 1, MEDIA_VIEW_EITHER = -1;

// Where uv, across a view's image, lies in its layers: a lamp's view of fewer texels than the array
// fills their first ones, and its lookups stay half a texel inside them, so a bilinear tap weighs
// the cleared texel beyond them 0. Other views, and every view where all are whole (share 1),
// keep uv as it is. The share comes from the header, not the view: worked out per lookup from the
// view's texel size, it cost campfire's opaque pass a millisecond.
vec2 mediaSliceLayerUv(vec4 params, int kind, vec2 uv) {
    bool lamp = kind == MEDIA_VIEW_EITHER ? params.x > 0.5 : kind == MEDIA_VIEW_PERSPECTIVE;
    return lamp ? min(uv * intBitsToFloat(mediaSliceCount.y), vec2(intBitsToFloat(mediaSliceCount.w))) : uv;
}

// The optical depth one light view's slices hold at a point with clip coordinates `clip` and view
// depth `depth` in that view. Both are linear in the point, so a host may interpolate them per vertex.
// `params`, `firstLayer`: the view's params and params2.x; `kind`: MEDIA_VIEW_*.
float mediaSliceOpticalDepthAt(vec4 params, float firstLayer, int kind, vec4 clip, float depth) {
    vec2 uv;
    if (!lightViewClipUv(clip, uv)) return 0.0;  // slices cover the medium: outside them there is none
    int K = int(params.w);
    float s = (depth - params.y) / (params.z - params.y) * float(K);
    if (s <= 0.0) return 0.0;
    // The enclosing interval, or the last one past the medium.
    int k = min(int(floor(s)), K - 1);
    vec4 q = texture(mediaSlices, vec3(mediaSliceLayerUv(params, kind, uv), firstLayer + float(k)));
    if (s >= float(K)) return q.z;
    // Monotone cubic Hermite between planes k and k + 1 (Fritsch and Carlson): the slopes from the
    // neighbours, limited to [0, 3δ] so τ never falls or overshoots its ends.
    float t = s - float(k), delta = q.z - q.y, most = 3.0 * max(delta, 0.0);
    float m0 = clamp(0.5 * (q.z - q.x), 0.0, most), m1 = clamp(0.5 * (q.w - q.y), 0.0, most);
    return q.y + t * (m0 + t * (3.0 * delta - 2.0 * m0 - m1 + t * (m0 + m1 - 2.0 * delta)));
}

float mediaViewOpticalDepthAt(GpuLightView v, int kind, vec4 clip, float depth) { return mediaSliceOpticalDepthAt(v.params, v.params2.x, kind, clip, depth); }

// MEDIA_SLICE_CROPS: the lookups below by light read a light's crop (count 2) where it holds p. It
// is a define, not a test of the count, because llvmpipe pays for the test's arithmetic on every
// lookup of every light (the exact tier's fragments: 6–9%); without it a light with a crop reads its
// whole view, which holds the same light, only coarser.
// A directional light may come with two views (count 2): the whole medium's, then a finer crop over
// where meshes reach into it: the same orthographic view shifted and narrowed across, with the same
// view depth, its planes from a little before the meshes to past them (media planning/slice_crop.h).
// Its first plane holds all the light has crossed before it; its near plane, one spacing before
// that, is not read. A point inside the crop's footprint and between its first and far planes reads
// the crop. `cropClip`: p's clip coordinates in the crop, `depth` its view depth (the same in both).
bool mediaInsideCrop(GpuLightView crop, vec4 cropClip, float depth) {
    float first = crop.params.y + (crop.params.z - crop.params.y) / crop.params.w;
    return all(lessThanEqual(abs(cropClip.xy), vec2(cropClip.w))) && depth >= first && depth <= crop.params.z;
}

// The crop's clip coordinates from the whole view's (w = 1): a scale and an offset across, cheaper
// than the crop's matrix for every lookup that might fall in it.
vec4 mediaCropClip(GpuLightView whole, GpuLightView crop, vec4 clip) {
    vec2 scale = whole.params2.zw / crop.params2.zw;
    return vec4(clip.xy * scale + (crop.viewProjection[3].xy - whole.viewProjection[3].xy * scale), 0.0, 1.0);
}

// Where the crop holds the point, its params, first layer and clip coordinates replace the whole
// view's: selected, not branched, so a lookup fetches once either way.
void mediaChooseCrop(GpuLightView crop, vec4 cropClip, float depth, inout vec4 params, inout float layer, inout vec4 clip) {
    bool inside = mediaInsideCrop(crop, cropClip, depth);
    params = inside ? crop.params : params;
    layer = inside ? crop.params2.x : layer;
    clip = inside ? cropClip : clip;
}

float mediaCroppedOpticalDepthAt(GpuLightView whole, GpuLightView crop, vec4 clip, vec4 cropClip, float depth) {
    vec4 params = whole.params;
    float layer = whole.params2.x;
    mediaChooseCrop(crop, cropClip, depth, params, layer, clip);
    return mediaSliceOpticalDepthAt(params, layer, MEDIA_VIEW_ORTHOGRAPHIC, clip, depth);  // a crop's light is directional
}

// The optical depth one light view's slices hold at p.
float mediaViewOpticalDepth(GpuLightView v, vec3 p) {
    return mediaViewOpticalDepthAt(v, MEDIA_VIEW_EITHER, v.viewProjection * vec4(p, 1.0), -(v.view * vec4(p, 1.0)).z);
}

// The view of host light `light` (at origin-relative `lightPosition`) whose slices hold p, or −1.
int mediaLightSliceView(int light, vec3 lightPosition, vec3 p) {
    if (mediaSliceCount.x == 0) return -1;
    ivec4 s = mediaLightSlices[light];
#ifdef MEDIA_SLICE_CROPS
    if (s.y == 2) {
        GpuLightView whole = mediaSliceViews[s.x];
        return mediaInsideCrop(mediaSliceViews[s.x + 1], mediaCropClip(whole, mediaSliceViews[s.x + 1], whole.viewProjection * vec4(p, 1.0)),
                               -(whole.view * vec4(p, 1.0)).z) ? s.x + 1 : s.x;
    }
#endif
    return s.x < 0 ? -1 : lightViewIndex(s.x, s.y, lightPosition, p);
}

// The view's matrices are its light's first view's (lightViewPoint): a cube face's are not read.
// `count`: the light's slice view count (1, 2 with a crop, or 6 for a point light), a constant
// where the caller knows it.
float mediaOpticalDepthOf(int light, int count, vec3 lightPosition, vec3 p) {
    int first = mediaLightSlices[light].x;
    if (mediaSliceCount.x == 0 || first < 0) return 0.0;
    int face = lightViewFace(count, lightPosition, p);
    float depth;
    vec4 clip = lightViewPoint(mediaSliceViews[first], count, face, lightPosition, p, depth);
    vec4 params = mediaSliceViews[first + face].params;
    float layer = mediaSliceViews[first + face].params2.x;
#ifdef MEDIA_SLICE_CROPS
    if (count == 2)
        mediaChooseCrop(mediaSliceViews[first + 1], mediaCropClip(mediaSliceViews[first], mediaSliceViews[first + 1], clip), depth, params,
                        layer, clip);
#endif
    return mediaSliceOpticalDepthAt(params, layer, count == 6 ? MEDIA_VIEW_PERSPECTIVE : MEDIA_VIEW_EITHER, clip, depth);
}

float mediaOpticalDepth(int light, vec3 lightPosition, vec3 p) {
    return mediaOpticalDepthOf(light, mediaLightSlices[light].y, lightPosition, p);
}

float mediaTransmittance(int light, vec3 lightPosition, vec3 p) { return exp(-mediaOpticalDepth(light, lightPosition, p)); }
