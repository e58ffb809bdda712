// One corner of a splat: the particle at `rank` in draw order, with the fit of its source the
// lighting pass computed (particle_lighting.comp): its linear part interpolated across the quad,
// the rest for the fragments. Needs common/frame, fog, media particle_data, billboard,
// particle_light_layout, the DrawOrder and ParticleLight buffers and splat_varyings (as out).
void splatVertex(int rank, vec2 corner) {
    int index = int(drawOrder[rank]);
    GpuParticle particle = particles[index];
    vec4 pr = particle.positionRadius;
    vFog = fogAtPoint(pr.xyz);
    vCentreRadius = pr;
    vSigma = particle.albedoSigma.w;
    vPhase = vec2(particle.extra.x, particle.emissionG.w);
    uint base = PARTICLE_LIGHT_STRIDE * uint(rank);
    vSun = particleLight[base + SUN_SLOT];
#ifdef MEDIA_MULTIPLE
    vPeakAlbedo = luminance(particle.albedoSigma.rgb);
#endif
#ifdef MEDIA_FRAGMENT_LAMPS
    vAlbedo = particle.albedoSigma.rgb;
#ifdef SPLAT_LAMP_ORDER
    vLayer = ivec2(index, rank);
#endif
#endif
    Billboard b = billboardOf(pr.xyz, pr.w);
#ifdef SPLAT_CONSTANT
    vSource = particleLight[base];
#else
    for (int k = 0; k < 4; ++k) vFit[k] = particleLight[base + 3u + uint(k)];
#ifdef MEDIA_MESH_CROSSINGS
    vCrossed = any(lessThan(vSun.rgb, vec3(0.0))) ? 1 : 0;
#endif
    vCorner = corner;
    vSource = particleLight[base];
    if (!b.coversScreen) vSource += particleLight[base + 1u] * corner.x + particleLight[base + 2u] * corner.y;
#endif
    vec3 onQuad = pr.xyz + b.right * corner.x + b.up * corner.y;
    gl_Position = b.coversScreen ? vec4(corner, 0.5, 1.0) : frame.viewProjection * vec4(onQuad, 1.0);
    // A perspective quad's corner is a point of its pixel's ray from the eye (the frame origin), and
    // interpolated perspective-correctly it stays one wherever the quad is clipped. Passed as the
    // ray through its screen position, linear on the screen (noperspective), the rays of particles
    // around the eye came out wrong (docs/design-notes.md).
    vRayOrigin = vec3(0.0);
    vRayDirection = onQuad;
    if (b.coversScreen || frameOrthographic()) cameraRayAtNdc(gl_Position.xy / gl_Position.w, vRayOrigin, vRayDirection);
}
