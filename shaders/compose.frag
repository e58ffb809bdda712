#version 450 core
// Compose (DESIGN.md §3 step 4): the media target holds in-scattered radiance (premultiplied) in
// rgb and the view transmittance in a, so final = media.rgb + media.a · opaque. Output is linear.
layout(binding = 0) uniform sampler2D uOpaque;
layout(binding = 1) uniform sampler2D uMedia;
layout(location = 0) uniform int uHasMedia;

layout(location = 0) out vec4 outRadiance;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 opaque = texelFetch(uOpaque, p, 0).rgb;
    if (uHasMedia == 0) {
        outRadiance = vec4(opaque, 1.0);
        return;
    }
    vec4 media = texelFetch(uMedia, p, 0);
    outRadiance = vec4(media.rgb + media.a * opaque, 1.0);
}
