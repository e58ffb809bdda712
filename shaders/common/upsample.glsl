// Depth-aware upsampling of a reduced-resolution translucent layer (Jendersie's offscreen particles):
// the four low-resolution texels around the pixel, weighted bilinearly, keep only those computed at
// this pixel's depth (within `threshold`, relative); where none was, the one closest in depth, so
// smoke does not bleed over the silhouette of a mesh in front of it. Dropping only the mismatched
// texels keeps a medium over sloping ground smooth. The four depths come in one gather.
// `depthUsed` must clamp to its edges (render/compose_pass.cpp binds a sampler that does).
//
// Mixed resolution (Cantlay, "High-Speed, Off-Screen Particles"): a pixel where any of the four
// texels was computed at another depth is an edge. A layer may come with its edges drawn at full
// resolution (MediaLayer::edges); the host takes those pixels from it. The plugin marks the same
// pixels with upsampleEdge, so both sides must call it with the same inputs.

// The four texels around a pixel: textureGather's order, (0, 1), (1, 1), (1, 0), (0, 0).
struct UpsampleTaps {
    ivec2 base;       // the (0, 0) texel
    vec4 bilinear;    // each one's bilinear weight
    vec4 difference;  // |depth it used − the pixel's depth|
    bvec4 match;      // computed at the pixel's depth
};

UpsampleTaps upsampleTaps(sampler2D depthUsed, vec2 fragCoord, vec2 scale, float depth, float threshold) {
    ivec2 lowSize = textureSize(depthUsed, 0);
    // Texel i of the low target stands for the full-resolution point (i + 0.5)/scale.
    vec2 p = fragCoord * scale - 0.5;
    vec2 base = floor(p);
    vec2 f = p - base;
    vec4 used = textureGather(depthUsed, (base + 1.0) / vec2(lowSize), 0);
    UpsampleTaps t;
    t.base = ivec2(base);
    t.bilinear = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
    t.difference = abs(used - depth);
    t.match = lessThanEqual(t.difference, threshold * min(vec4(depth), used));
    return t;
}

// Whether the pixel is an edge: some texel around it was computed at another depth.
bool upsampleEdge(UpsampleTaps t) { return !all(t.match); }

vec4 upsampleLayer(sampler2D layer, UpsampleTaps t) {
    vec4 weight = t.bilinear * vec4(t.match);
    float total = dot(weight, vec4(1.0));
    if (!(total > 1e-3)) {
        float closest = min(min(t.difference.x, t.difference.y), min(t.difference.z, t.difference.w));
        weight = vec4(equal(t.difference, vec4(closest)));
        total = dot(weight, vec4(1.0));
    }
    ivec2 b = t.base, top = textureSize(layer, 0) - 1;
    vec4 sum = weight.x * texelFetch(layer, clamp(b + ivec2(0, 1), ivec2(0), top), 0) +
               weight.y * texelFetch(layer, clamp(b + ivec2(1, 1), ivec2(0), top), 0) +
               weight.z * texelFetch(layer, clamp(b + ivec2(1, 0), ivec2(0), top), 0) +
               weight.w * texelFetch(layer, clamp(b, ivec2(0), top), 0);
    return sum / max(total, 1e-30);
}

vec4 upsampleLayer(sampler2D layer, sampler2D depthUsed, vec2 fragCoord, vec2 scale, float depth, float threshold) {
    return upsampleLayer(layer, upsampleTaps(depthUsed, fragCoord, scale, depth, threshold));
}
