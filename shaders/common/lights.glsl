// KHR_lights_punctual lights (render/frame_data.h GpuLight). sampleLight mirrors the CPU definition
// in assets/light_model.h: inverse square, glTF range window, spot cone (scale/offset form).
struct GpuLight {
    vec4 position;   // xyz origin-relative, w: range (0 infinite)
    vec4 direction;  // xyz travel direction, w: type 0 directional, 1 point, 2 spot
    vec4 radiance;   // rgb colour × intensity
    vec4 spot;       // x: cone scale, y: cone offset, z: first shadow view, w: shadow view count
    vec4 media;      // x: first transmittance view, y: view count
};

layout(std430, binding = 0) readonly buffer Lights { GpuLight lights[]; };

struct LightSample {
    vec3 toLight;     // unit
    float distance;   // 1e30 for directional lights
    vec3 irradiance;  // on a surface facing the light, before any visibility
};

LightSample sampleLight(int index, vec3 p) {
    GpuLight L = lights[index];
    int type = int(L.direction.w + 0.5);
    if (type == 0) return LightSample(-L.direction.xyz, 1e30, L.radiance.rgb);
    vec3 d = L.position.xyz - p;
    float dist = length(d);
    if (dist < 1e-9) return LightSample(vec3(0.0, 1.0, 0.0), dist, vec3(0.0));
    vec3 l = d / dist;
    float attenuation = 1.0 / (dist * dist);
    if (L.position.w > 0.0) {
        float r = dist / L.position.w;
        float window = clamp(1.0 - r * r * r * r, 0.0, 1.0);
        attenuation *= window * window;
    }
    if (type == 2) {
        float a = clamp(dot(L.direction.xyz, -l) * L.spot.x + L.spot.y, 0.0, 1.0);
        attenuation *= a * a;
    }
    return LightSample(l, dist, L.radiance.rgb * attenuation);
}
