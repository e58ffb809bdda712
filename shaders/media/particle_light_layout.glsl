// The per-particle lighting buffer (media/particle_lighting_pass.cpp), per rank in draw order: J0
// (w: how far in front of its closest approach the centre ray's light is seen), gx, gy, r (the
// source's fit over the billboard, particle_lighting.comp), then per fragment-evaluated lamp the
// part of its light taken per particle (albedo × mesh visibility).
const int MAX_FRAGMENT_LAMPS = 2;
const uint PARTICLE_LIGHT_STRIDE = 7u + uint(MAX_FRAGMENT_LAMPS);

// The point or spot lights whose 1/d² the fragments evaluate (−1: none); every other light is
// taken per particle.
layout(location = 8) uniform int uFragmentLamps[MAX_FRAGMENT_LAMPS];

bool litPerFragment(int light) {
    for (int k = 0; k < MAX_FRAGMENT_LAMPS; ++k)
        if (uFragmentLamps[k] == light) return true;
    return false;
}
