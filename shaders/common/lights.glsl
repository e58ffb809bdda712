// KHR_lights_punctual lights (gpu/frame_layout.h GpuLight). sampleLight mirrors the CPU definition
// in assets/light_model.h: inverse square, glTF range window, spot cone (scale/offset form).
struct GpuLight {
    vec4 position;   // xyz origin-relative, w: range (0 infinite)
    vec4 direction;  // xyz travel direction, w: type 0 directional, 1 point, 2 spot
    vec4 radiance;   // rgb colour × intensity
    vec4 spot;       // x: cone scale, y: cone offset, z: first shadow view, w: shadow view count
};

// A uniform block, not a storage buffer: llvmpipe loads uniforms 3–4× faster, and every pixel of
// the opaque pass reads a light and its views (gpu/frame_layout.h kMaxLights).
const int MAX_LIGHTS = 64;
layout(std140, binding = 1) uniform Lights { GpuLight lights[MAX_LIGHTS]; };

struct LightSample {
    vec3 toLight;     // unit
    float distance;   // 1e30 for directional lights
    vec3 irradiance;  // on a surface facing the light, before any visibility
};

// The point/spot light's falloff at p apart from 1/d²: the range window times the spot cone.
float lightShape(int index, vec3 p) {
    GpuLight L = lights[index];
    vec3 d = L.position.xyz - p;
    float dist = length(d);
    float shape = 1.0;
    if (L.position.w > 0.0) {
        float r = dist / L.position.w;
        float window = clamp(1.0 - r * r * r * r, 0.0, 1.0);
        shape *= window * window;
    }
    if (int(L.direction.w + 0.5) == 2 && dist > 0.0) {
        float a = clamp(dot(L.direction.xyz, -d / dist) * L.spot.x + L.spot.y, 0.0, 1.0);
        shape *= a * a;
    }
    return shape;
}

LightSample sampleLight(int index, vec3 p) {
    GpuLight L = lights[index];
    if (int(L.direction.w + 0.5) == 0) return LightSample(-L.direction.xyz, 1e30, L.radiance.rgb);
    vec3 d = L.position.xyz - p;
    float dist = length(d);
    if (dist < 1e-9) return LightSample(vec3(0.0, 1.0, 0.0), dist, vec3(0.0));
    return LightSample(d / dist, dist, L.radiance.rgb * (lightShape(index, p) / (dist * dist)));
}
