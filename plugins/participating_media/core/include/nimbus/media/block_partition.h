#pragma once
// Groups particles into blocks (seed 000 §2): Morton-ordered chunks of equal size.
//
// Why Morton chunks: every block gets the same number of particles, so impostor work is balanced;
// consecutive Morton codes are spatially compact, so a block's impostor is small on screen; the
// codes live on a lattice anchored in world space (cell = the largest power of two not above the
// mean particle radius), so a block's members change only where particles cross lattice cells,
// not when the medium's bounds move — the grouping is stable from frame to frame and
// deterministic (stable sort, ties by particle index).
//
// Block count: fixed by the caller (`--set blocks=N`, a scene's render.blocks) or chosen by the
// seed's cost model. Simulation and impostor work grow as b + N/b for N particles in blocks of b,
// which is smallest at b = √N, so the automatic count is round(√N), clamped to [1, 1024].
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/media/particle_set.h"

namespace nimbus::media {

struct Block {
    std::uint32_t first = 0;   // into BlockPartition::order
    std::uint32_t count = 0;
    glm::dvec3 centre{0.0};    // mean of the member centres (world)
    double radius = 0.0;       // bounding sphere of the members' spheres around `centre`
    float meanParticleRadius = 0.0f;
};

struct BlockPartition {
    std::vector<std::uint32_t> order;  // particle indices, block by block
    std::vector<Block> blocks;
};

int automaticBlockCount(std::size_t particles);

// Splits `particles` into min(blockCount, N) blocks (blockCount <= 0: automatic).
BlockPartition partitionIntoBlocks(const ParticleSet& particles, int blockCount);

// Morton code of a non-negative lattice cell (21 bits per axis); exposed for tests.
std::uint64_t mortonCode(std::uint32_t x, std::uint32_t y, std::uint32_t z);

}  // namespace nimbus::media
