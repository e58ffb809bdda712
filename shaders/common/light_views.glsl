// Views from a light (gpu/frame_layout.h GpuLightView), shared by shadow maps and transmittance slices.
const int MAX_LIGHT_VIEWS = 384;  // per kind, in one uniform block (gpu/frame_layout.h kMaxLightViews)
struct GpuLightView {
    mat4 view;
    mat4 viewProjection;
    vec4 params;   // x: perspective, y: depth near, z: depth far, w: slice count
    vec4 params2;  // x: first layer, y: texel size at depth 1, zw: half extent
};

// Which of a light's views sees p: the cube face for six-view point lights, else the only one.
int lightViewIndex(int first, int count, vec3 lightPosition, vec3 p) {
    return count == 6 ? first + cubeFace(p - lightPosition) : first;
}

// Where a point with clip coordinates `clip` in a light view falls in the view's texture: false when
// it lies behind the view or outside it.
bool lightViewClipUv(vec4 clip, out vec2 uv) {
    uv = clip.xy / max(clip.w, 1e-30) * 0.5 + 0.5;
    return clip.w > 0.0 && all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
}

bool lightViewUv(GpuLightView v, vec3 p, out vec2 uv) { return lightViewClipUv(v.viewProjection * vec4(p, 1.0), uv); }
