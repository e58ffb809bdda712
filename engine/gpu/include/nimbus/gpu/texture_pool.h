#pragma once
// The GL ResourceAllocator: transient frame-graph textures are pooled by description and reused
// across frames, so a steady frame allocates nothing. Textures unused for a few frames are freed.
#include <memory>
#include <vector>

#include "nimbus/gpu/frame_graph.h"

namespace nimbus::gpu {

class TexturePool final : public ResourceAllocator {
public:
    const Texture* acquire(const TextureDesc& desc) override;
    void release(const Texture* texture) override;
    void endFrame();  // ages free textures and frees the stale ones
    std::size_t size() const { return entries_.size(); }

private:
    struct Entry {
        std::unique_ptr<Texture> texture;
        bool inUse = false;
        int idleFrames = 0;
    };
    std::vector<Entry> entries_;
};

}  // namespace nimbus::gpu
