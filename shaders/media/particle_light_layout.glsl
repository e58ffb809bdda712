// The per-particle lighting buffer (media/particle_lighting_pass.cpp), per rank in draw order:
//   0..6  the fit F0, gx, gy, r2, r4, cx, cy (particle_lighting.comp), rgb the source of all but
//         the fragments' sun and lamps, a the sun's transport
//   7     rgb albedo × the sun's radiance, w how far in front of its closest approach the centre
//         ray's light is seen
//   8..   per fragment-evaluated lamp, what of its light is taken per particle (albedo × mesh visibility)
const int MAX_FRAGMENT_LAMPS = 2;
const uint PARTICLE_LIGHT_STRIDE = 8u + uint(MAX_FRAGMENT_LAMPS);

// The lights the fragments evaluate (−1: none): the first directional light, whose phase function
// can peak within a few pixels, and the point or spot lights whose 1/d² peaks across a particle.
layout(location = 7) uniform int uFragmentSun;
layout(location = 8) uniform int uFragmentLamps[MAX_FRAGMENT_LAMPS];

bool litPerFragment(int light) {
    if (light == uFragmentSun) return true;
    for (int k = 0; k < MAX_FRAGMENT_LAMPS; ++k)
        if (uFragmentLamps[k] == light) return true;
    return false;
}
