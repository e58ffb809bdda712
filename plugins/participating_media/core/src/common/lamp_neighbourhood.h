#pragma once
// The particles around each point and spot light, for particles mode (shaders/media/
// lamp_neighbourhood.glsl). Particles composite as whole layers in back-to-front order of their
// centres, so a layer's light is dimmed by every particle drawn after it and by none drawn before,
// wherever their mass lies along the ray. Near a lamp that misorders a 1/d² peak that holds most of
// a pixel's light (docs/design-notes.md); with the overlapping particles listed, the
// fragment shader replaces that attenuation with the exact optical depth in front of the peak.
//
// Does not: list neighbours of directional lights (no peak), or more than kMaxLampNeighbours per
// lamp (the closest ones, relative to their radius, are kept).
#include <cstdint>
#include <vector>

#include "nimbus/media/gpu_bindings.h"
#include "nimbus/media/host.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/media/particle_set.h"

namespace nimbus::media {

inline constexpr std::size_t kMaxLampNeighbours = 128;

// Whether any of `lights` is a point or spot light (a lamp, with a 1/d² peak).
bool anyLamp(const std::vector<Light>& lights);

// One lamp's entry in the buffer's header: its neighbours are entries [first, first + count).
struct LampNeighbourhood {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    float reach = 0.0f;  // the correction applies within `reach` of the lamp, fading out from reach/2
};

// Which lamps get a neighbourhood.
enum class LampsListed {
    // Lamps inside the medium (particles mode: outside it, compositing order gets the peak right).
    InsideMedium,
    // Every lamp near the medium (blocks mode: a block's uniform density is wrong near any lamp).
    // Reach is at least the caller's minimum (a lamp outside every particle: at least the radius
    // of the particle nearest it); where more than kMaxLampNeighbours particles come within it,
    // the closest by the gap between sphere and lamp are kept and reach shrinks to the first gap
    // left out, so the list stays complete within reach.
    All,
};

// The neighbourhoods of `lights`, in their order: for a lamp inside the medium, reach is the
// largest radius of the particles containing it, and the neighbours are the particles whose sphere
// comes within reach of it (so any particle containing a point within reach is listed), each with
// its layer's rank (`rankOf[particle]`: its place in the back-to-front draw order, or its block's).
// A frame without point or spot lights does no work.
class LampNeighbourhoods {
public:
    // Recomputes everything; storage is reused, so steady frames allocate nothing.
    void find(const ParticleSet& particles, const std::vector<Light>& lights,
              const std::vector<std::uint32_t>& rankOf, LampsListed which, double minimumReach = 0.0);

    std::vector<LampNeighbourhood> lamps;
    std::vector<glm::uvec2> neighbours;  // x: particle index, y: its layer's rank

private:
    std::vector<std::pair<double, std::uint32_t>> candidates_;
};

// The GPU copy: header (one per light) followed by the neighbour entries, in one std430 buffer.
class LampNeighbourhoodBuffer {
public:
    void upload(const LampNeighbourhoods& neighbourhoods);
    void bind() const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLampNeighbourhoodBinding, buffer_.id()); }

private:
    gpu::Buffer buffer_;
    std::size_t capacity_ = 0;
    std::vector<std::uint32_t> staging_;
};

}  // namespace nimbus::media
