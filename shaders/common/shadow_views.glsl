// The mesh shadow-map views (gpu/frame_layout.h: SSBO binding 1). Needs light_views.glsl and frame.glsl.
layout(std140, binding = 2) uniform ShadowViews { GpuLightView shadowViews[MAX_LIGHT_VIEWS]; };

// Where uv, across view v's whole image ([0, 1]²), lies in its layer. A point light's face is drawn
// in the first params.w of each side (render/shadow_pass.cpp); its lookups stay half a texel inside
// that corner, so a bilinear tap never weighs a texel beyond it. Other views keep uv as it is.
vec2 shadowLayerUv(GpuLightView v, vec2 uv) {
    float share = v.params.w;
    return share < 1.0 ? min(uv * share, vec2(share - 0.5 / float(frame.counts.z))) : uv;
}

// The shadow lookup's offset off the surface: along the normal by a texel-sized amount at view
// depth `depth` in view v, to avoid acne.
float shadowOffset(GpuLightView v, float depth) { return 1.5 * (v.params2.y * (v.params.x > 0.5 ? depth : 1.0)); }
