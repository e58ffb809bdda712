#pragma once
// Groups particles into blocks (seed 000 §2) by recursive median bisection: the particles of a
// range of blocks are split at the median of their longest axis, in the ratio of the block counts
// on either side, until each range is one block.
//
// Why median bisection: every block gets the same number of particles (±1), so impostor work is
// balanced; every block is a compact box of space, so its impostor is small on screen and its
// [front, back] interval tight (Morton-order chunks, tried first, straddle the jumps of the
// Z curve: a block could hold both ends of a cloud); and it is stable: it depends only on the
// particles' relative order along the axes (ties broken by particle index), so moving the whole
// medium changes nothing and one particle moving changes a few memberships near split planes.
//
// Block count: fixed by the caller (`--set blocks=N`, a scene's render.blocks) or automatic. The
// seed's cost model — simulation and colour work b + N/b for N particles in blocks of b — is
// smallest at b = √N, i.e. √N blocks. A block's assumed density profile (seed 000 §2.4: uniform)
// errs where a mesh cuts it, and less the smaller it is: on content/scenes/cloud.gltf (500
// particles, 320×180), with uniform density and one shading point per block, the error in the band
// around the wing was 3.5% with √N = 22 blocks, 2.0% with 50, for 1.3× the frame time. So the
// automatic count is round(2√N), clamped to [1, 2048]. With the depth profile and two shading
// points (shaders/media/block_lighting.glsl) that band is 1.2% at 2√N.
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


}  // namespace nimbus::media
