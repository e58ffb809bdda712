// Depth-aware upsampling of a reduced-resolution translucent layer (Jendersie's offscreen particles):
// the four low-resolution texels around the pixel, weighted bilinearly, keep only those computed at
// this pixel's depth (within `threshold`, relative); where none was, the one closest in depth, so
// smoke does not bleed over the silhouette of a mesh in front of it. Dropping only the mismatched
// texels keeps a medium over sloping ground smooth. The four depths come in one gather.
// `depthUsed` must clamp to its edges (render/compose_pass.cpp binds a sampler that does).
vec4 upsampleLayer(sampler2D layer, sampler2D depthUsed, vec2 fragCoord, vec2 scale, float depth, float threshold) {
    ivec2 lowSize = textureSize(layer, 0);
    // Texel i of the low target stands for the full-resolution point (i + 0.5)/scale.
    vec2 p = fragCoord * scale - 0.5;
    vec2 base = floor(p);
    vec2 f = p - base;
    // textureGather's order: (0, 1), (1, 1), (1, 0), (0, 0) around the point between four centres.
    vec4 used = textureGather(depthUsed, (base + 1.0) / vec2(lowSize), 0);
    vec4 bilinear = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
    vec4 difference = abs(used - depth);
    vec4 weight = bilinear * vec4(lessThanEqual(difference, threshold * min(vec4(depth), used)));
    float total = dot(weight, vec4(1.0));
    if (!(total > 1e-3)) {
        float closest = min(min(difference.x, difference.y), min(difference.z, difference.w));
        weight = vec4(equal(difference, vec4(closest)));
        total = dot(weight, vec4(1.0));
    }
    ivec2 b = ivec2(base), top = lowSize - 1;
    vec4 sum = weight.x * texelFetch(layer, clamp(b + ivec2(0, 1), ivec2(0), top), 0) +
               weight.y * texelFetch(layer, clamp(b + ivec2(1, 1), ivec2(0), top), 0) +
               weight.z * texelFetch(layer, clamp(b + ivec2(1, 0), ivec2(0), top), 0) +
               weight.w * texelFetch(layer, clamp(b, ivec2(0), top), 0);
    return sum / max(total, 1e-30);
}
