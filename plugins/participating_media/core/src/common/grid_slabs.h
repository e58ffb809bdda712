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

#include <glm/glm.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

namespace nimbus::media {

// Grids smaller than this many voxels run on the calling thread: a task's overhead would outweigh
// its share (the coarse levels the diffusion starts from are a few hundred voxels).
inline constexpr long kParallelVoxels = 4096;

// slab(z) for every z in [0, slabs), in parallel; `slabVoxels`: the voxels of one slab.
template <class Slab>
void forEachSlab(int slabs, long slabVoxels, const Slab& slab) {
    if (static_cast<long>(slabs) * slabVoxels < kParallelVoxels) {
        for (int z = 0; z < slabs; ++z) slab(z);
        return;
    }
    const int grain = static_cast<int>(std::max(1L, kParallelVoxels / 4 / std::max(slabVoxels, 1L)));
    tbb::parallel_for(tbb::blocked_range<int>(0, slabs, grain), [&](const tbb::blocked_range<int>& r) {
        for (int z = r.begin(); z != r.end(); ++z) slab(z);
    });
}

// The component-wise largest of slab(z) (a float or a glm vector) over every z in [0, slabs), from
// `zero`, in parallel: a maximum is the same in any order.
template <class T, class Slab>
T largestOverSlabs(int slabs, long slabVoxels, T zero, const Slab& slab) {
    auto larger = [](const T& a, const T& b) { return glm::max(a, b); };
    if (static_cast<long>(slabs) * slabVoxels < kParallelVoxels) {
        T largest = zero;
        for (int z = 0; z < slabs; ++z) largest = larger(largest, slab(z));
        return largest;
    }
    const int grain = static_cast<int>(std::max(1L, kParallelVoxels / 4 / std::max(slabVoxels, 1L)));
    return tbb::parallel_reduce(
        tbb::blocked_range<int>(0, slabs, grain), zero,
        [&](const tbb::blocked_range<int>& r, T largest) {
            for (int z = r.begin(); z != r.end(); ++z) largest = larger(largest, slab(z));
            return largest;
        },
        larger);
}

}  // namespace nimbus::media
