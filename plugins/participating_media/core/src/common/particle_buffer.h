#pragma once
// The GPU copy of a ParticleSet: one std430 instance buffer (shaders/media/common/particle_data.glsl)
// with positions relative to the frame origin, and a back-to-front draw order for the camera.
#include <vector>

#include "common/lamp_neighbourhood.h"
#include "nimbus/media/gpu_bindings.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/gpu/view.h"

namespace nimbus::media {


struct alignas(16) GpuParticle {
    glm::vec4 positionRadius;
    glm::vec4 albedoSigma;
    glm::vec4 emissionG;
    glm::vec4 extra;  // x: phase (0 HG, 1 Rayleigh)
};

// How far in front of its centre, along a ray through it, a particle's seen light lies: where its
// own optical depth from the ray's entry reaches the e^−v-weighted mean v̄ (shaders/media/common/optics.glsl
// shadingDepthFraction), for a ray through the centre of a particle of radius R and peak
// extinction σ. 0 for a thin particle (v̄ = τ/2: the centre), towards R for a dense one (its front).
// Sorting by centres put a dense particle whose front lies far in front of another's behind it
// (docs/design-notes.md).
double visibleDepthOffset(double sigma, double radius);

// `order` ← 0..n−1 sorted by `keys` from the largest to the smallest, equal keys in index order:
// what std::stable_sort with `>` gives, in four linear passes of an LSD radix sort (10⁶ particles
// a frame). `scratch` is reused between calls.
void sortDescending(const std::vector<float>& keys, std::vector<std::uint32_t>& order, std::vector<std::uint32_t>& scratch);

class ParticleGpuBuffer {
public:
    // Rewrites the instance buffer (grows it when needed; never shrinks, so steady frames allocate nothing).
    void upload(const ParticleSet& particles, const glm::dvec3& origin);
    // Sorts by the distance from the eye to where each particle's light is seen (visibleDepthOffset
    // in front of its centre), farthest first, and uploads the order.
    void sortBackToFront(const ParticleSet& particles, const gpu::View& view);
    // Sorts by the centres' depth along the view axis, farthest first (sheets mode: the particles
    // that reach into a sheet are one run of ranks), and uploads the order.
    void sortByViewDepth(const ParticleSet& particles, const gpu::View& view);
    // After sorting: the particle index at each rank (what the DrawOrder buffer holds).
    const std::vector<std::uint32_t>& order() const { return order_cpu_; }
    // After sortByViewDepth: the view depth of the particle at each rank (non-increasing).
    const std::vector<float>& rankDepths() const { return rankDepths_; }

    // After sorting: the particles around each point/spot light, with their draw ranks (particles mode).
    void uploadLampNeighbourhoods(const ParticleSet& particles, const std::vector<Light>& lights);
    // The same with each particle's layer rank given (blocks mode: its block's place in the draw order).
    void uploadLampNeighbourhoods(const ParticleSet& particles, const std::vector<Light>& lights,
                                  const std::vector<std::uint32_t>& rankOf, LampsListed which, double minimumReach = 0.0);

    void bindParticles() const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kParticlesBinding, particles_.id()); }
    void bindOrder() const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDrawOrderBinding, order_.id()); }
    void bindLampNeighbourhoods() const { lampBuffer_.bind(); }
    std::size_t count() const { return count_; }

private:
    gpu::Buffer particles_, order_;
    std::size_t particleCapacity_ = 0, orderCapacity_ = 0, count_ = 0;
    std::vector<GpuParticle> staging_;
    std::vector<std::uint32_t> order_cpu_;
    std::vector<float> keys_;
    std::vector<float> rankDepths_;
    std::vector<std::uint32_t> sortScratch_;
    // visibleDepthOffset per particle and the (σ, R) it was computed for: recomputed only where
    // they changed (its erf inverse is the costliest step of the sort at 10⁶ particles).
    std::vector<double> offsets_;
    std::vector<glm::vec2> offsetInputs_;
    std::vector<std::uint32_t> rank_;
    LampNeighbourhoods lamps_;
    LampNeighbourhoodBuffer lampBuffer_;
};

}  // namespace nimbus::media
