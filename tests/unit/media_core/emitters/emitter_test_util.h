#pragma once
// Helpers shared by the emitter tests: stepping a simulation the way every host does (t0 = k·dt,
// the node's matrix at both ends of the step) and comparing particle arrays bit for bit.
#include <cstring>
#include <functional>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "nimbus/media/emitter_simulation.h"

namespace nimbus::media::test {

using NodePath = std::function<glm::dmat4(double)>;

inline NodePath translation(const glm::dvec3& t) {
    return [t](double) { return glm::translate(glm::dmat4(1.0), t); };
}

// Steps k = first, ..., first + count - 1.
inline void runSteps(EmitterSimulation& s, int count, double dt, const NodePath& node, int first = 0) {
    for (int k = first; k < first + count; ++k) {
        const double t0 = static_cast<double>(k) * dt;
        s.step(t0, dt, node(t0), node(static_cast<double>(k + 1) * dt));
    }
}

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

inline bool bitIdentical(const EmitterParticles& a, const EmitterParticles& b) {
    return sameBits(a.position, b.position) && sameBits(a.velocity, b.velocity) && sameBits(a.age, b.age) &&
           sameBits(a.lifetime, b.lifetime) && sameBits(a.sizeScale, b.sizeScale);
}

}  // namespace nimbus::media::test
