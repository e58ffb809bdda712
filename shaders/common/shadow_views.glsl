// The mesh shadow-map views (gpu/frame_layout.h: SSBO binding 1). Needs light_views.glsl.
layout(std140, binding = 2) uniform ShadowViews { GpuLightView shadowViews[MAX_LIGHT_VIEWS]; };
