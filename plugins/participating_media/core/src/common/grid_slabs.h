#pragma once
// The multiple model's grid loops (environment_grid.h, diffusion.h) split over z slabs on TBB's
// threads. A frame whose medium moved solves the grid again on the CPU, so an animated plume pays
// it every frame. Each slab's voxels are computed only from what no slab writes in the same loop
// (a red-black half-sweep's other colour, or another array), and the only reduction is a maximum,
// so the grid is the same bit for bit on any number of threads.
//
// Does not: choose the thread count (TBB's default arena: all cores, or what a host's
// tbb::task_arena or tbb::global_control allows; docs/integration.md).
#include <algorithm>
#include <cstddef>

#include <glm/glm.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

namespace nimbus::media {

// Grids smaller than this many voxels run on the calling thread: a task's overhead would outweigh
// its share (the coarse levels the diffusion starts from are a few hundred voxels).
inline constexpr long kParallelVoxels = 4096;

inline long slabVoxels(const glm::ivec3& size) { return static_cast<long>(size.x) * size.y; }
inline bool onCallingThread(const glm::ivec3& size) { return slabVoxels(size) * size.z < kParallelVoxels; }
// The z slabs of a grid of `size`, about a quarter of kParallelVoxels a task.
inline tbb::blocked_range<int> slabRange(const glm::ivec3& size) {
    const auto grain = static_cast<std::size_t>(std::max(1L, kParallelVoxels / 4 / std::max(slabVoxels(size), 1L)));
    return tbb::blocked_range<int>(0, size.z, grain);
}

// slab(z) for every z slab of a grid of `size`, in parallel.
template <class Slab>
void forEachSlab(const glm::ivec3& size, const Slab& slab) {
    if (onCallingThread(size)) {
        for (int z = 0; z < size.z; ++z) slab(z);
        return;
    }
    tbb::parallel_for(slabRange(size), [&](const tbb::blocked_range<int>& r) {
        for (int z = r.begin(); z != r.end(); ++z) slab(z);
    });
}

// The component-wise largest of slab(z) (a float or a glm vector) over every z slab of a grid of
// `size`, from `zero`, in parallel: a maximum is the same in any order.
template <class T, class Slab>
T largestOverSlabs(const glm::ivec3& size, T zero, const Slab& slab) {
    auto larger = [](const T& a, const T& b) { return glm::max(a, b); };
    if (onCallingThread(size)) {
        T largest = zero;
        for (int z = 0; z < size.z; ++z) largest = larger(largest, slab(z));
        return largest;
    }
    return tbb::parallel_reduce(
        slabRange(size), zero,
        [&](const tbb::blocked_range<int>& r, T largest) {
            for (int z = r.begin(); z != r.end(); ++z) largest = larger(largest, slab(z));
            return largest;
        },
        larger);
}

}  // namespace nimbus::media
