// The mesh shadow-map views (gpu/frame_layout.h: SSBO binding 1). Needs light_views.glsl.
layout(std140, binding = 2) uniform ShadowViews { GpuLightView shadowViews[MAX_LIGHT_VIEWS]; };

// The shadow lookup's offset off the surface: along the normal by a texel-sized amount at view
// depth `depth` in view v, to avoid acne.
float shadowOffset(GpuLightView v, float depth) { return 1.5 * (v.params2.y * (v.params.x > 0.5 ? depth : 1.0)); }
