// mini_host's uniform blocks (frame_blocks.h). Names carry a "mini" prefix so they never meet the
// names of Nimbus's shared includes that the media hook pulls in.
layout(std140, binding = 0) uniform MiniFrame {
    mat4 viewProjection;  // camera-relative world → clip (reversed Z)
    vec4 ambient;         // rgb: L_amb
    ivec4 counts;         // x lights, y shadow map size, z PCF radius
} miniFrame;

struct MiniLight {
    vec4 position;   // xyz camera-relative, w range (0: infinite)
    vec4 direction;  // xyz travel direction, w kind (0 directional, 1 point, 2 spot)
    vec4 radiance;   // rgb colour × intensity
    vec4 spot;       // x cone scale, y cone offset, z first shadow view (−1: none), w view count
};
const int MINI_MAX_LIGHTS = 64;
layout(std140, binding = 1) uniform MiniLights { MiniLight miniLights[MINI_MAX_LIGHTS]; };

struct MiniShadowView {
    mat4 view;
    mat4 viewProjection;
    vec4 params;  // x perspective, y texel size (metres, at depth 1 when perspective), z layer
};
const int MINI_MAX_SHADOW_VIEWS = 384;
layout(std140, binding = 2) uniform MiniShadowViews { MiniShadowView miniShadowViews[MINI_MAX_SHADOW_VIEWS]; };

const float MINI_INV_PI = 0.31830988618379067154;
