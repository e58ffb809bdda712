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

// d = p − the light in the view of its cube face `face` (gpu/light_views.h cubeFaceView): xy across
// the face (its NDC is xy / z), z the view depth. The faces are OpenGL's cube-map faces: a signed
// swizzle, no matrix.
vec3 cubeFaceView(int face, vec3 d) {
    vec3 v = face < 2 ? vec3(-d.z, -d.y, d.x) : face < 4 ? vec3(d.x, d.z, d.y) : vec3(d.x, -d.y, d.z);
    bool yFace = face == 2 || face == 3;
    return (face & 1) == 0 ? v : vec3(yFace ? v.x : -v.x, yFace ? -v.y : v.y, -v.z);
}

// A lookup into a light's views reads only the few numbers of the view that holds p that a cube
// face does not share with the first: neighbouring lanes see different faces, and llvmpipe loads
// a face's matrices lane by lane. Both ways are computed and one chosen before the one fetch
// (llvmpipe runs both sides of a branch); it pays where `count` is a compile-time constant, which
// folds the other way away. `single` is the light's first view: a one-view light's matrices.
// lightViewFace: the face (0 for a one-view light); lightViewPoint: p's clip coordinates (a cube
// face's with z = 0: its planes give it) and, in w, its view depth.
int lightViewFace(int count, vec3 lightPosition, vec3 p) { return count == 6 ? cubeFace(p - lightPosition) : 0; }

vec4 lightViewPoint(GpuLightView single, int count, int face, vec3 lightPosition, vec3 p, out float depth) {
    vec3 c = cubeFaceView(face, p - lightPosition);
    vec4 h = vec4(p, 1.0);
    depth = count == 6 ? c.z : -(single.view * h).z;
    return count == 6 ? vec4(c.xy, 0.0, c.z) : single.viewProjection * h;
}

// Where a point with clip coordinates `clip` in a light view falls in the view's texture: false when
// it lies behind the view or outside it.
bool lightViewClipUv(vec4 clip, out vec2 uv) {
    uv = clip.xy / max(clip.w, 1e-30) * 0.5 + 0.5;
    return clip.w > 0.0 && all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
}

bool lightViewUv(GpuLightView v, vec3 p, out vec2 uv) { return lightViewClipUv(v.viewProjection * vec4(p, 1.0), uv); }
