#pragma once
// A small frame graph (after Filament's): each pass declares in a setup step which textures it
// creates, reads and writes; compile() culls passes whose results nobody uses and works out each
// transient texture's lifetime; execute() runs the survivors in order, acquiring textures from an
// allocator just before first use and releasing them after last use, and times every pass.
//
// Does not: reorder passes (declaration order is execution order), alias memory beyond what the
// allocator's pool does, or insert barriers (GL orders draws for us).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "nimbus/gpu/gl_objects.h"

namespace nimbus::gpu {

struct ResourceHandle {
    std::uint32_t index = UINT32_MAX;
    bool valid() const { return index != UINT32_MAX; }
    bool operator==(const ResourceHandle&) const = default;
};

// Where transient textures come from. The GL one pools textures across frames; tests use one that
// never touches GL (the no-op backend).
class ResourceAllocator {
public:
    virtual ~ResourceAllocator() = default;
    virtual const Texture* acquire(const TextureDesc& desc) = 0;
    virtual void release(const Texture* texture) = 0;
};

// Receives per-pass timings. The GL timer synchronises (glFinish) around each pass.
class PassTimer {
public:
    virtual ~PassTimer() = default;
    virtual void begin(std::string_view pass) = 0;
    virtual void end(std::string_view pass) = 0;
};

class FrameGraph;

class PassBuilder {
public:
    ResourceHandle create(std::string name, const TextureDesc& desc);
    ResourceHandle read(ResourceHandle resource);
    ResourceHandle write(ResourceHandle resource);
    void sideEffect();  // the pass matters by itself (it reads back, presents, or fills imported data)

private:
    friend class FrameGraph;
    PassBuilder(FrameGraph& graph, std::uint32_t pass) : graph_(graph), pass_(pass) {}
    FrameGraph& graph_;
    std::uint32_t pass_;
};

class PassResources {
public:
    const Texture& texture(ResourceHandle resource) const;
    GLuint id(ResourceHandle resource) const { return texture(resource).id(); }
    const TextureDesc& desc(ResourceHandle resource) const;

private:
    friend class FrameGraph;
    explicit PassResources(const FrameGraph& graph) : graph_(graph) {}
    const FrameGraph& graph_;
};

class FrameGraph {
public:
    explicit FrameGraph(ResourceAllocator& allocator) : allocator_(allocator) {}
    FrameGraph(const FrameGraph&) = delete;
    FrameGraph& operator=(const FrameGraph&) = delete;

    // setup runs now; execute runs in execute() if the pass survives culling.
    template <typename Data>
    const Data& addPass(std::string name, const std::function<void(PassBuilder&, Data&)>& setup,
                        std::function<void(const PassResources&, const Data&)> execute) {
        auto data = std::make_shared<Data>();
        const std::uint32_t index = beginPass(std::move(name));
        PassBuilder builder(*this, index);
        setup(builder, *data);
        passes_[index].execute = [data, run = std::move(execute)](const PassResources& r) { run(r, *data); };
        return *data;
    }

    // A texture owned outside the graph (persistent across frames, or the caller's output).
    ResourceHandle importTexture(std::string name, const Texture& texture);

    // The handle of a named resource, or an invalid handle (passes find each other's outputs by name).
    ResourceHandle find(std::string_view name) const;
    const TextureDesc& desc(ResourceHandle resource) const;

    // Keeps a transient texture past execute(): its writers survive culling, and instead of going
    // back to the allocator it stays with the caller, who reads it through extracted() and hands
    // it back with ResourceAllocator::release when done (a plugin's output read after the graph).
    void extract(ResourceHandle resource);
    const Texture* extracted(ResourceHandle resource) const;  // after execute(); null if never acquired

    void compile();
    void execute(PassTimer* timer = nullptr);

    // After compile(): which passes run, in order (for tests and stats).
    std::vector<std::string> activePasses() const;

private:
    friend class PassBuilder;
    friend class PassResources;

    struct Resource {
        std::string name;
        TextureDesc desc;
        const Texture* texture = nullptr;  // imported, or acquired during execute
        bool imported = false;
        bool extracted = false;
        std::int64_t firstUse = -1;
        std::int64_t lastUse = -1;
    };
    struct Pass {
        std::string name;
        std::vector<std::uint32_t> reads;
        std::vector<std::uint32_t> writes;
        bool sideEffect = false;
        bool alive = false;
        std::function<void(const PassResources&)> execute;
    };

    std::uint32_t beginPass(std::string name);
    std::uint32_t addResource(Resource resource);

    ResourceAllocator& allocator_;
    std::vector<Resource> resources_;
    std::vector<Pass> passes_;
    bool compiled_ = false;
};

}  // namespace nimbus::gpu
