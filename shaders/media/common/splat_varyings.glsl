// What a splat's vertices hand its fragments (particle_splats.*, sheets/sheet_splats.*): define
// SPLAT_VARYING as `out` in a vertex shader and `in` in a fragment shader before including this.
flat SPLAT_VARYING vec4 vCentreRadius;  // origin-relative centre, radius
flat SPLAT_VARYING float vSigma;
// The pixel's camera ray, its direction not normalised (splat_vertex.glsl): a point on the quad
// (perspective) or cameraRayAtNdc's (orthographic and screen-covering quads, whose w is 1).
SPLAT_VARYING vec3 vRayOrigin;
SPLAT_VARYING vec3 vRayDirection;
flat SPLAT_VARYING float vFog;           // the fog factor at the centre (common/fog.glsl)
#ifdef SPLAT_CONSTANT
flat SPLAT_VARYING vec4 vSource;        // F0
#else
SPLAT_VARYING vec4 vSource;             // F0 + gx·x + gy·y (an affine function of the billboard's plane: exact)
SPLAT_VARYING vec2 vCorner;             // x, y
flat SPLAT_VARYING vec4 vFit[4];        // r2, r4, cx, cy
#ifdef MEDIA_MESH_CROSSINGS
flat SPLAT_VARYING int vCrossed;        // 1 where a mesh crosses the particle (splat_source.glsl), else 0
#endif
#endif
flat SPLAT_VARYING vec4 vSun;           // rgb: albedo × the sun's radiance, a: the centre ray's shading offset
flat SPLAT_VARYING vec2 vPhase;         // phase function (0 HG, 1 Rayleigh), g
#ifdef MEDIA_MULTIPLE
flat SPLAT_VARYING float vPeakAlbedo;  // the albedo the sun's peak orders take (common/peak_orders.glsl)
#endif
#ifdef MEDIA_FRAGMENT_LAMPS
flat SPLAT_VARYING vec3 vAlbedo;        // the lamps' light per fragment is scattered with it
#ifdef SPLAT_LAMP_ORDER
flat SPLAT_VARYING ivec2 vLayer;        // the particle's index and draw rank (lamp_neighbourhood.glsl)
#endif
#endif
