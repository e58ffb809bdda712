// KHR_lights_punctual irradiance: inverse square for point and spot lights, the glTF range window
// clamp(1 − (d/range)⁴, 0, 1)², the spot cone a² with a = clamp(cosθ·scale + offset, 0, 1).
// Needs mini_frame.glsl.

// The falloff of point or spot light i at p apart from 1/d²: range window × spot cone.
float miniLightShape(int i, vec3 p) {
    MiniLight L = miniLights[i];
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

// Irradiance at p on a surface facing light i, before visibility; `toLight` is unit.
vec3 miniIrradiance(int i, vec3 p, out vec3 toLight) {
    MiniLight L = miniLights[i];
    if (int(L.direction.w + 0.5) == 0) {
        toLight = -L.direction.xyz;
        return L.radiance.rgb;
    }
    vec3 d = L.position.xyz - p;
    float dist = length(d);
    if (dist < 1e-9) {
        toLight = vec3(0.0, 1.0, 0.0);
        return vec3(0.0);
    }
    toLight = d / dist;
    return L.radiance.rgb * (miniLightShape(i, p) / (dist * dist));
}
