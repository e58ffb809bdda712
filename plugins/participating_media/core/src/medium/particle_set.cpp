#include "nimbus/media/particle_set.h"

namespace nimbus::media {

void ParticleSet::clear() {
    position.clear();
    radius.clear();
    sigma.clear();
    albedo.clear();
    emission.clear();
    g.clear();
    phase.clear();
}

void ParticleSet::reserve(std::size_t n) {
    position.reserve(n);
    radius.reserve(n);
    sigma.reserve(n);
    albedo.reserve(n);
    emission.reserve(n);
    g.reserve(n);
    phase.reserve(n);
}

void ParticleSet::push(const glm::dvec3& p, float r, float s, const Medium& medium) {
    position.push_back(p);
    radius.push_back(r);
    sigma.push_back(s);
    albedo.push_back(medium.albedo);
    emission.push_back(medium.emission);
    g.push_back(medium.g);
    phase.push_back(medium.phase);
}

void ParticleSet::append(const ParticleSet& o) {
    position.insert(position.end(), o.position.begin(), o.position.end());
    radius.insert(radius.end(), o.radius.begin(), o.radius.end());
    sigma.insert(sigma.end(), o.sigma.begin(), o.sigma.end());
    albedo.insert(albedo.end(), o.albedo.begin(), o.albedo.end());
    emission.insert(emission.end(), o.emission.begin(), o.emission.end());
    g.insert(g.end(), o.g.begin(), o.g.end());
    phase.insert(phase.end(), o.phase.begin(), o.phase.end());
}

}  // namespace nimbus::media
