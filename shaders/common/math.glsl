// Constants and small helpers shared by every pass.
const float PI = 3.14159265358979323846;
const float INV_PI = 0.31830988618379067154;
const float INV_4PI = 0.07957747154594766788;

float saturate(float x) { return clamp(x, 0.0, 1.0); }

// Rec. 709 luminance of linear RGB (the weights the C++ side's kLuminanceWeights holds).
float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// 1 − exp(−x) without cancellation for small x (opacity from optical depth).
float oneMinusExpNeg(float x) {
    return x < 1e-3 ? x * (1.0 - x * (0.5 - x * (1.0 / 6.0))) : 1.0 - exp(-x);
}

// The cube face of a direction: 0..5 = +X −X +Y −Y +Z −Z (gpu/light_views.h cubeFace).
int cubeFace(vec3 d) {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
    return d.z >= 0.0 ? 4 : 5;
}
