#version 450 core
// Light-slice upscale (media/slices/light_slice_upscale_pass.cpp): one covering triangle per layer
// of a view drawn small, instance i to the view's layer uTargetLayer + i. UPSCALE_ONE_LAYER (no
// ARB_shader_viewport_layer_array): one layer a draw, the one attached.
#ifndef UPSCALE_ONE_LAYER
#extension GL_ARB_shader_viewport_layer_array : require
#endif
layout(location = 0) uniform int uTargetLayer;  // the view's first layer in the slice array
layout(location = 1) uniform int uSourceLayer;  // its first layer in the small array

flat out int vSourceLayer;

void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));  // (0,0), (2,0), (0,2)
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
#ifndef UPSCALE_ONE_LAYER
    gl_Layer = uTargetLayer + gl_InstanceID;
#endif
    vSourceLayer = uSourceLayer + gl_InstanceID;
}
