// The per-particle lighting buffer (media/particle_lighting_pass.cpp), per rank in draw order:
//   0..6  the fit F0, gx, gy, r2, r4, cx, cy (particle_lighting.comp), rgb the source of all but
//         the fragments' sun and lamps, a the sun's transport
//   7     rgb albedo × the sun's radiance (negated where a mesh crosses the particle: the fit's a
//         then holds the medium's transmittance alone), w how far in front of its closest approach
//         the centre ray's light is seen
// SPLAT_CONSTANT (particles of a few pixels, where a fit has nothing to follow): F0 alone, then
// the slot that is 7 above.
const int MAX_FRAGMENT_LAMPS = 2;
#ifdef SPLAT_CONSTANT
const uint PARTICLE_LIGHT_STRIDE = 2u;
const uint SUN_SLOT = 1u;
#else
const uint PARTICLE_LIGHT_STRIDE = 8u;
const uint SUN_SLOT = 7u;
#endif

// The lights the fragments evaluate (−1: none): the first directional light, whose phase function
// can peak within a few pixels, and the point or spot lights whose 1/d² peaks across a particle.
layout(location = 7) uniform int uFragmentSun;
layout(location = 8) uniform int uFragmentLamps[MAX_FRAGMENT_LAMPS];

// Set by particle_lighting.comp per particle: no lamp lies near it, so the fit carries every lamp
// and its fragments (drawn without MEDIA_FRAGMENT_LAMPS) evaluate none.
bool gLampsInFit = false;

bool litPerFragment(int light) {
    if (light == uFragmentSun) return true;
    if (gLampsInFit) return false;
    for (int k = 0; k < MAX_FRAGMENT_LAMPS; ++k)
        if (uFragmentLamps[k] == light) return true;
    return false;
}
