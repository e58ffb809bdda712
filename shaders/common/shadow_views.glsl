// The mesh shadow-map views (render/frame_data.h: SSBO binding 1). Needs light_views.glsl.
layout(std430, binding = 1) readonly buffer ShadowViews { GpuLightView shadowViews[]; };
