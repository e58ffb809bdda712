// The light slices inside the plugin's own shaders, by light index. Needs common/lights.glsl.
#include "media/host/light_transmittance.glsl"

float mediumOpticalDepth(int i, vec3 p) { return mediaOpticalDepth(i, lights[i].position.xyz, p); }
float mediumOpticalDepthOf(int i, int views, vec3 p) { return mediaOpticalDepthOf(i, views, lights[i].position.xyz, p); }
