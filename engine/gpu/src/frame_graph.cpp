#include "nimbus/gpu/frame_graph.h"

#include <algorithm>
#include <stdexcept>

namespace nimbus::gpu {

ResourceHandle PassBuilder::create(std::string name, const TextureDesc& desc) {
    FrameGraph::Resource resource;
    resource.name = std::move(name);
    resource.desc = desc;
    const std::uint32_t index = graph_.addResource(std::move(resource));
    graph_.passes_[pass_].writes.push_back(index);
    return {index};
}

ResourceHandle PassBuilder::read(ResourceHandle resource) {
    if (!resource.valid() || resource.index >= graph_.resources_.size())
        throw std::logic_error("frame graph: pass " + graph_.passes_[pass_].name + " reads an invalid resource");
    graph_.passes_[pass_].reads.push_back(resource.index);
    return resource;
}

ResourceHandle PassBuilder::write(ResourceHandle resource) {
    if (!resource.valid() || resource.index >= graph_.resources_.size())
        throw std::logic_error("frame graph: pass " + graph_.passes_[pass_].name + " writes an invalid resource");
    graph_.passes_[pass_].writes.push_back(resource.index);
    return resource;
}

void PassBuilder::sideEffect() { graph_.passes_[pass_].sideEffect = true; }

const Texture& PassResources::texture(ResourceHandle resource) const {
    const auto& r = graph_.resources_.at(resource.index);
    if (r.texture == nullptr) throw std::logic_error("frame graph: resource " + r.name + " used outside its lifetime");
    return *r.texture;
}

const TextureDesc& PassResources::desc(ResourceHandle resource) const {
    return graph_.resources_.at(resource.index).desc;
}

std::uint32_t FrameGraph::beginPass(std::string name) {
    if (compiled_) throw std::logic_error("frame graph: pass " + name + " added after compile()");
    passes_.push_back(Pass{std::move(name), {}, {}, false, false, {}});
    return static_cast<std::uint32_t>(passes_.size() - 1);
}

std::uint32_t FrameGraph::addResource(Resource resource) {
    if (find(resource.name).valid()) throw std::logic_error("frame graph: resource " + resource.name + " declared twice");
    resources_.push_back(std::move(resource));
    return static_cast<std::uint32_t>(resources_.size() - 1);
}

ResourceHandle FrameGraph::importTexture(std::string name, const Texture& texture) {
    Resource resource;
    resource.name = std::move(name);
    resource.desc = texture.desc();
    resource.texture = &texture;
    resource.imported = true;
    return {addResource(std::move(resource))};
}

ResourceHandle FrameGraph::find(std::string_view name) const {
    for (std::size_t i = 0; i < resources_.size(); ++i)
        if (resources_[i].name == name) return {static_cast<std::uint32_t>(i)};
    return {};
}

const TextureDesc& FrameGraph::desc(ResourceHandle resource) const { return resources_.at(resource.index).desc; }

void FrameGraph::compile() {
    // Walk backwards: a pass lives if it has a side effect, or if a living later pass reads
    // something it writes. Declaration order is execution order, so one sweep suffices.
    std::vector<bool> neededResource(resources_.size(), false);
    for (std::size_t r = 0; r < resources_.size(); ++r) neededResource[r] = resources_[r].extracted;
    for (std::size_t p = passes_.size(); p-- > 0;) {
        Pass& pass = passes_[p];
        pass.alive = pass.sideEffect ||
                     std::any_of(pass.writes.begin(), pass.writes.end(), [&](std::uint32_t r) { return neededResource[r]; });
        if (!pass.alive) continue;
        for (std::uint32_t r : pass.reads) neededResource[r] = true;
        // A pass that writes part of a resource may depend on an earlier pass filling the rest.
        for (std::uint32_t r : pass.writes) neededResource[r] = true;
    }
    for (auto& r : resources_) r.firstUse = r.lastUse = -1;
    for (std::size_t p = 0; p < passes_.size(); ++p) {
        if (!passes_[p].alive) continue;
        auto touch = [&](std::uint32_t r) {
            auto& res = resources_[r];
            if (res.firstUse < 0) res.firstUse = static_cast<std::int64_t>(p);
            res.lastUse = static_cast<std::int64_t>(p);
        };
        for (std::uint32_t r : passes_[p].reads) touch(r);
        for (std::uint32_t r : passes_[p].writes) touch(r);
    }
    compiled_ = true;
}

void FrameGraph::execute(PassTimer* timer) {
    if (!compiled_) compile();
    PassResources view(*this);
    for (std::size_t p = 0; p < passes_.size(); ++p) {
        Pass& pass = passes_[p];
        if (!pass.alive) continue;
        for (auto& r : resources_)
            if (!r.imported && r.firstUse == static_cast<std::int64_t>(p)) r.texture = allocator_.acquire(r.desc);
        if (timer) timer->begin(pass.name);
        pass.execute(view);
        if (timer) timer->end(pass.name);
        for (auto& r : resources_)
            if (!r.imported && !r.extracted && r.lastUse == static_cast<std::int64_t>(p)) {
                allocator_.release(r.texture);
                r.texture = nullptr;
            }
    }
}

void FrameGraph::extract(ResourceHandle resource) { resources_.at(resource.index).extracted = true; }

const Texture* FrameGraph::extracted(ResourceHandle resource) const {
    const Resource& r = resources_.at(resource.index);
    return r.extracted ? r.texture : nullptr;
}

std::vector<std::string> FrameGraph::activePasses() const {
    std::vector<std::string> names;
    for (const auto& p : passes_)
        if (p.alive) names.push_back(p.name);
    return names;
}

}  // namespace nimbus::gpu
