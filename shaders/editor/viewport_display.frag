#version 450 core
// The editor viewport's display pass: the renderer's linear output as 8-bit sRGB display values,
// exactly as PNG writing encodes them (assets/image_io: L clamped to [0, 1], IEC 61966-2-1), and
// flipped so row 0 is the top as ImGui draws images.
layout(binding = 0) uniform sampler2D uRadiance;

layout(location = 0) out vec4 outDisplay;

float srgbEncode(float linear) {
    if (!(linear > 0.0)) return 0.0;  // NaN too
    if (linear >= 1.0) return 1.0;
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

void main() {
    ivec2 size = textureSize(uRadiance, 0);
    ivec2 p = ivec2(gl_FragCoord.x, size.y - 1 - int(gl_FragCoord.y));
    vec3 radiance = texelFetch(uRadiance, p, 0).rgb;
    outDisplay = vec4(srgbEncode(radiance.r), srgbEncode(radiance.g), srgbEncode(radiance.b), 1.0);
}
