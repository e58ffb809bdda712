#pragma once
// Groups particles into blocks (Umenhoffer and Szirmay-Kalos §2) by recursive median bisection: the particles of a
// range of blocks are split at the median of their longest axis, in the ratio of the block counts
// on either side, until each range is one block.
//
// Why median bisection: every block gets the same number of particles (±1), so impostor work is
// balanced; every block is a compact box of space, so its impostor is small on screen and its
// [front, back] interval tight (Morton-order chunks straddle the jumps of the Z curve); and it is
// stable: it depends only on the particles' relative order along the axes (ties broken by particle
// index), so moving the whole medium changes nothing and one particle moving changes a few
// memberships near split planes.
//
// Block count: fixed by the caller (`--set blocks=N`, a scene's render.blocks) or automatic. The
// seed's cost model — simulation and colour work b + N/b for N particles in blocks of b — is
// smallest at b = √N, i.e. √N blocks. A block's assumed density profile (Umenhoffer and Szirmay-Kalos §2.4) errs where
// a mesh cuts it, and less the smaller it is, so the cost-model count is round(2√N), clamped to
// [1, 2048] (docs/design-notes.md).
//
// A block is shaded as one layer with one depth profile, which holds while light changes little
// across it; in a dense medium a block of several particles shadows itself in lumps the profile
// does not have. So where the median block's thickness at that count (its mean optical depth
// through it, blockThickness) exceeds 0.5, about where its own transmittance varies by e^−0.5, the
// automatic count doubles round(3·log2(median / 0.5)) times, at most to N/2: each doubling thins
// blocks by 2^(1/3). The cost model's partition is the one measured, and kept when it is thin
// enough, so a thin medium is partitioned once per frame, a thick one twice (docs/design-notes.md).
//
// A point or spot light among the particles lights a block with 1/d², which varies across a block
// of radius r at distance d by ((d + r)/(d − r))², 16× at r/d = 0.6: more than a block's one
// shading profile holds. So where the median block's lamp spread (r/d to the nearest lamp) exceeds
// 0.6 — a lamp inside the medium, not beside it — the automatic count doubles once. Once, not by
// the cube-root rule above: d does not shrink with the blocks, and more blocks are not safe
// everywhere (docs/design-notes.md).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/media/host.h"
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

inline constexpr int kMaxBlocks = 2048;
// Blocks thicker than this (the median over blocks of blockThickness) are made smaller: see above.
inline constexpr double kMaxBlockThickness = 0.5;
// Blocks are doubled once where the median block's radius over its distance to the nearest point or
// spot light exceeds this: see above.
inline constexpr double kMaxLampSpread = 0.6;

// The world positions of the point and spot lights among `lights` (what the automatic count looks at).
std::vector<glm::dvec3> lampPositions(const std::vector<Light>& lights);

// The cost model's count, round(2√N) clamped to [1, kMaxBlocks] (0 for no particles).
int costModelBlockCount(std::size_t particles);

// The count partitionIntoBlocks(particles, 0, lamps) makes (by making it): the cost model's, doubled
// where its median block is thicker than kMaxBlockThickness or nearer a lamp than kMaxLampSpread
// allows (see above). `lamps`: the world positions of the scene's point and spot lights.
int automaticBlockCount(const ParticleSet& particles, const std::vector<glm::dvec3>& lamps = {});

// A block's mean optical depth through it: its members' kernel mass over its bounding sphere's
// cross-section (a ray through a uniform ball of that mass sees this on average).
double blockThickness(const ParticleSet& particles, const BlockPartition& partition, const Block& block);

// A block's radius over its centre's distance to the nearest of `lamps` (above 1: a lamp inside it).
double lampSpread(const Block& block, const std::vector<glm::dvec3>& lamps);

// Where some lamp sees a block wider than this, the lamps' slices (block_slice_pass.cpp; every
// lamp's, so that one flag per block says what they hold) take its particles one by one, in place
// of the block's light impostor. The impostor spreads a block's optical depth along each lamp ray
// as one normal, and a block whose radius is comparable to its distance from the lamp spans along
// a ray about as much as the ray is long: r/d = 0.5 is where the block's depth span reaches its
// distance (docs/design-notes.md). Blocks mode's light side then costs particles mode's for those
// particles, in lamp views only.
inline constexpr double kMaxLampImpostorSpread = 0.5;

// Per block (1/0): whether some lamp sees it wider than kMaxLampImpostorSpread.
std::vector<std::uint8_t> blocksSeenWideFromLamps(const BlockPartition& partition, const std::vector<glm::dvec3>& lamps);

// Compositing blocks back to front dims a block's light by the whole of every block drawn after it
// and by none of those drawn before it. Where two blocks' spheres overlap, a ray may meet part of
// each in front of the other, and the order is wrong for that part. Where a mesh is seen in the
// medium, block_composite.frag makes the overlapping neighbours' attenuation exact by their depth
// profiles (shaders/media/blocks/block_order.glsl), for the neighbours listed here (docs/design-notes.md).
inline constexpr std::size_t kMaxOrderNeighbours = 32;

// Per block, the blocks whose bounding spheres overlap its own, nearest centres first, at most
// kMaxOrderNeighbours, as one array: `blocks` headers (first entry, count), then the entries
// (block, its rank in `backToFront`).
std::vector<glm::uvec2> overlappingBlockLists(const BlockPartition& partition, const std::vector<std::uint32_t>& backToFront);

// Splits `particles` into min(blockCount, N) blocks (blockCount <= 0: automatic, which looks at
// `lamps` as automaticBlockCount does).
BlockPartition partitionIntoBlocks(const ParticleSet& particles, int blockCount, const std::vector<glm::dvec3>& lamps = {});


}  // namespace nimbus::media
