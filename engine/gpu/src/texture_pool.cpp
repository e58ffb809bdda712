#include "nimbus/gpu/texture_pool.h"

#include <algorithm>

namespace nimbus::gpu {

namespace {
constexpr int kMaxIdleFrames = 3;
}

const Texture* TexturePool::acquire(const TextureDesc& desc) {
    TextureDesc normalized = desc;
    normalized.depth = std::max(normalized.depth, 1);
    normalized.levels = std::max(normalized.levels, 1);
    for (auto& e : entries_) {
        if (e.inUse || !(e.texture->desc() == normalized)) continue;
        e.inUse = true;
        e.idleFrames = 0;
        return e.texture.get();
    }
    entries_.push_back({std::make_unique<Texture>(normalized), true, 0});
    return entries_.back().texture.get();
}

void TexturePool::release(const Texture* texture) {
    for (auto& e : entries_)
        if (e.texture.get() == texture) e.inUse = false;
}

void TexturePool::endFrame() {
    for (auto& e : entries_)
        if (!e.inUse) ++e.idleFrames;
    entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                  [](const Entry& e) { return !e.inUse && e.idleFrames > kMaxIdleFrames; }),
                   entries_.end());
}

}  // namespace nimbus::gpu
