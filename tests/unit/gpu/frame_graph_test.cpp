// FrameGraph without GL: a fake ResourceAllocator hands out default-constructed (name-less)
// textures and logs every acquire/release, so culling, lifetimes and reuse are observable.
#include "nimbus/gpu/frame_graph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace nimbus::gpu {
namespace {

// Pools textures by description like TexturePool, but never touches GL: the Texture objects are
// empty handles whose addresses identify them.
class FakeAllocator final : public ResourceAllocator {
public:
    explicit FakeAllocator(std::vector<std::string>& log) : log_(log) {}

    const Texture* acquire(const TextureDesc& desc) override {
        for (auto& slot : slots_)
            if (!slot.inUse && slot.desc == desc) {
                slot.inUse = true;
                log_.push_back("acquire " + name(&slot.texture));
                return &slot.texture;
            }
        slots_.push_back({});
        slots_.back().desc = desc;
        slots_.back().inUse = true;
        names_[&slots_.back().texture] = "T" + std::to_string(slots_.size() - 1);
        log_.push_back("acquire " + name(&slots_.back().texture));
        ++created;
        return &slots_.back().texture;
    }

    void release(const Texture* texture) override {
        log_.push_back("release " + name(texture));
        for (auto& slot : slots_)
            if (&slot.texture == texture) {
                EXPECT_TRUE(slot.inUse) << "released twice: " << name(texture);
                slot.inUse = false;
                return;
            }
        ADD_FAILURE() << "released a texture this allocator never gave out";
    }

    std::string name(const Texture* texture) const {
        const auto it = names_.find(texture);
        return it == names_.end() ? "foreign" : it->second;
    }
    bool anyInUse() const {
        return std::any_of(slots_.begin(), slots_.end(), [](const Slot& s) { return s.inUse; });
    }

    int created = 0;

private:
    struct Slot {
        Texture texture;
        TextureDesc desc;
        bool inUse = false;
    };
    std::vector<std::string>& log_;
    std::deque<Slot> slots_;  // stable addresses
    std::map<const Texture*, std::string> names_;
};

const TextureDesc kColor{GL_TEXTURE_2D, GL_RGBA32F, 64, 32, 1, 1};
const TextureDesc kDepth{GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, 64, 32, 1, 1};

struct Handles {
    ResourceHandle a, b, c;
};

class FrameGraphTest : public ::testing::Test {
protected:
    std::vector<std::string> log;
    FakeAllocator allocator{log};
    FrameGraph graph{allocator};

    // A pass whose execute logs "run NAME" and the allocator names of the textures it touches.
    void addLoggedPass(const std::string& name, const std::function<void(PassBuilder&, Handles&)>& setup) {
        graph.addPass<Handles>(name, setup, [this, name](const PassResources& r, const Handles& h) {
            std::string line = "run " + name;
            for (const ResourceHandle handle : {h.a, h.b, h.c})
                if (handle.valid()) line += " " + allocator.name(&r.texture(handle));
            log.push_back(line);
        });
    }

    std::size_t position(const std::string& entry) const {
        const auto it = std::find(log.begin(), log.end(), entry);
        EXPECT_NE(it, log.end()) << "log lacks \"" << entry << "\"";
        return static_cast<std::size_t>(it - log.begin());
    }
    bool logged(const std::string& entry) const { return std::find(log.begin(), log.end(), entry) != log.end(); }
};

TEST_F(FrameGraphTest, CullsPassesWhoseOutputsNobodyReads) {
    addLoggedPass("unused", [](PassBuilder& b, Handles& h) { h.a = b.create("unused_color", kColor); });
    addLoggedPass("producer", [](PassBuilder& b, Handles& h) { h.a = b.create("color", kColor); });
    addLoggedPass("present", [this](PassBuilder& b, Handles& h) {
        h.a = b.read(graph.find("color"));
        b.sideEffect();
    });
    graph.compile();
    EXPECT_EQ(graph.activePasses(), (std::vector<std::string>{"producer", "present"}));
    graph.execute();
    EXPECT_FALSE(logged("run unused"));
    EXPECT_EQ(allocator.created, 1) << "the culled pass's texture must never be acquired";
    EXPECT_FALSE(allocator.anyInUse());
}

TEST_F(FrameGraphTest, CullingPropagatesBackwardsThroughChains) {
    // feeds_dead → dead (culled: nobody reads dead's output) ; feeds_live → live → present.
    addLoggedPass("feeds_dead", [](PassBuilder& b, Handles& h) { h.a = b.create("x", kColor); });
    addLoggedPass("dead", [this](PassBuilder& b, Handles& h) {
        h.a = b.read(graph.find("x"));
        h.b = b.create("y", kColor);
    });
    addLoggedPass("feeds_live", [](PassBuilder& b, Handles& h) { h.a = b.create("p", kColor); });
    addLoggedPass("live", [this](PassBuilder& b, Handles& h) {
        h.a = b.read(graph.find("p"));
        h.b = b.create("q", kDepth);
    });
    addLoggedPass("present", [this](PassBuilder& b, Handles& h) {
        h.a = b.read(graph.find("q"));
        b.sideEffect();
    });
    graph.compile();
    EXPECT_EQ(graph.activePasses(), (std::vector<std::string>{"feeds_live", "live", "present"}));
}

TEST_F(FrameGraphTest, KeepsSideEffectPassesWithoutOutputs) {
    int runs = 0;
    graph.addPass<Handles>(
        "readback", [](PassBuilder& b, Handles&) { b.sideEffect(); }, [&](const PassResources&, const Handles&) { ++runs; });
    graph.addPass<Handles>(
        "pointless", [](PassBuilder&, Handles&) {}, [&](const PassResources&, const Handles&) { runs += 100; });
    graph.execute();  // compiles implicitly
    EXPECT_EQ(runs, 1);
    EXPECT_EQ(graph.activePasses(), std::vector<std::string>{"readback"});
}

TEST_F(FrameGraphTest, KeepsAnEarlierWriterOfAResourceALaterLivePassWrites) {
    // "clear" fills x, "draw" writes into it as well: draw's output depends on clear having run.
    addLoggedPass("clear", [](PassBuilder& b, Handles& h) { h.a = b.create("x", kColor); });
    addLoggedPass("draw", [this](PassBuilder& b, Handles& h) {
        h.a = b.write(graph.find("x"));
        b.sideEffect();
    });
    graph.compile();
    EXPECT_EQ(graph.activePasses(), (std::vector<std::string>{"clear", "draw"}));
}

TEST_F(FrameGraphTest, AcquiresBeforeFirstUseReleasesAfterLastUseAndReusesReleasedTextures) {
    // a: p1..p2, b: p2..p3, c: p3..p4. All share one description, so c can take a's texture,
    // which was released after p2; b overlaps a and must be a different texture.
    addLoggedPass("p1", [](PassBuilder& b, Handles& h) { h.a = b.create("a", kColor); });
    addLoggedPass("p2", [this](PassBuilder& b, Handles& h) {
        h.a = b.read(graph.find("a"));
        h.b = b.create("b", kColor);
    });
    addLoggedPass("p3", [this](PassBuilder& b, Handles& h) {
        h.a = b.read(graph.find("b"));
        h.b = b.create("c", kColor);
    });
    addLoggedPass("p4", [this](PassBuilder& b, Handles& h) {
        h.a = b.read(graph.find("c"));
        b.sideEffect();
    });
    graph.execute();

    const std::vector<std::string> expected = {
        "acquire T0", "run p1 T0",                     // a acquired just before p1
        "acquire T1", "run p2 T0 T1", "release T0",    // b acquired before p2; a released after its last use
        "acquire T0", "run p3 T1 T0", "release T1",    // c reuses a's texture
        "run p4 T0",  "release T0"};
    EXPECT_EQ(log, expected);
    EXPECT_EQ(allocator.created, 2);
    EXPECT_FALSE(allocator.anyInUse());
}

TEST_F(FrameGraphTest, DifferentDescriptionsAreNotReused) {
    addLoggedPass("p1", [](PassBuilder& b, Handles& h) { h.a = b.create("a", kColor); });
    addLoggedPass("p2", [this](PassBuilder& b, Handles& h) {
        h.a = b.read(graph.find("a"));
        h.b = b.create("d", kDepth);
    });
    addLoggedPass("p3", [this](PassBuilder& b, Handles& h) {
        h.a = b.read(graph.find("d"));
        b.sideEffect();
    });
    graph.execute();
    EXPECT_EQ(allocator.created, 2);
    EXPECT_LT(position("release T0"), position("run p3 T1"));
}

TEST_F(FrameGraphTest, ImportedTexturesAreNeverAcquiredOrReleased) {
    const Texture output;  // no GL name: the graph must only pass its address around
    const ResourceHandle imported = graph.importTexture("output", output);
    EXPECT_EQ(graph.find("output"), imported);
    addLoggedPass("draw", [](PassBuilder& b, Handles& h) { h.a = b.create("color", kColor); });
    const Texture* seen = nullptr;
    graph.addPass<Handles>(
        "compose",
        [&](PassBuilder& b, Handles& h) {
            h.a = b.read(graph.find("color"));
            h.b = b.write(imported);
            b.sideEffect();
        },
        [&](const PassResources& r, const Handles& h) { seen = &r.texture(h.b); });
    graph.execute();
    EXPECT_EQ(seen, &output);
    EXPECT_EQ(allocator.created, 1);
    EXPECT_FALSE(logged("release foreign"));
    EXPECT_EQ(std::count_if(log.begin(), log.end(), [](const std::string& s) { return s.rfind("acquire", 0) == 0; }), 1);
}

TEST_F(FrameGraphTest, ExtractedTexturesOutliveTheGraphUntilTheCallerReleasesThem) {
    // Nobody in the graph reads "result": extracting it keeps its writer alive, and its texture
    // stays acquired after execute, for the caller to read and hand back.
    addLoggedPass("producer", [](PassBuilder& b, Handles& h) { h.a = b.create("result", kColor); });
    const ResourceHandle result = graph.find("result");
    graph.extract(result);
    graph.compile();
    EXPECT_EQ(graph.activePasses(), (std::vector<std::string>{"producer"}));
    graph.execute();
    const Texture* texture = graph.extracted(result);
    ASSERT_NE(texture, nullptr);
    EXPECT_TRUE(allocator.anyInUse()) << "an extracted texture is not released by the graph";
    allocator.release(texture);
    EXPECT_FALSE(allocator.anyInUse());
}

TEST_F(FrameGraphTest, FindsResourcesByName) {
    ResourceHandle created;
    graph.addPass<Handles>(
        "p", [&](PassBuilder& b, Handles&) { created = b.create("scene_color", kColor); },
        [](const PassResources&, const Handles&) {});
    EXPECT_TRUE(created.valid());
    EXPECT_EQ(graph.find("scene_color"), created);
    EXPECT_EQ(graph.desc(created), kColor);
    EXPECT_FALSE(graph.find("scene_depth").valid());
    EXPECT_FALSE(graph.find("").valid());
}

TEST_F(FrameGraphTest, RefusesInvalidHandles) {
    EXPECT_THROW(graph.addPass<Handles>(
                     "reads_nothing", [](PassBuilder& b, Handles&) { b.read(ResourceHandle{}); },
                     [](const PassResources&, const Handles&) {}),
                 std::logic_error);
    EXPECT_THROW(graph.addPass<Handles>(
                     "writes_out_of_range", [](PassBuilder& b, Handles&) { b.write(ResourceHandle{42}); },
                     [](const PassResources&, const Handles&) {}),
                 std::logic_error);
    try {
        graph.addPass<Handles>(
            "named_in_message", [](PassBuilder& b, Handles&) { b.read(ResourceHandle{7}); },
            [](const PassResources&, const Handles&) {});
        ADD_FAILURE() << "no exception";
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("named_in_message"), std::string::npos) << e.what();
    }
}

TEST_F(FrameGraphTest, RefusesDuplicateNames) {
    graph.addPass<Handles>(
        "p", [](PassBuilder& b, Handles&) { b.create("color", kColor); }, [](const PassResources&, const Handles&) {});
    EXPECT_THROW(graph.addPass<Handles>(
                     "q", [](PassBuilder& b, Handles&) { b.create("color", kDepth); },
                     [](const PassResources&, const Handles&) {}),
                 std::logic_error);
    const Texture texture;
    EXPECT_THROW(graph.importTexture("color", texture), std::logic_error);
}

TEST_F(FrameGraphTest, RefusesPassesAddedAfterCompile) {
    graph.compile();
    EXPECT_THROW(graph.addPass<Handles>(
                     "late", [](PassBuilder&, Handles&) {}, [](const PassResources&, const Handles&) {}),
                 std::logic_error);
}

TEST_F(FrameGraphTest, RefusesTexturesUsedOutsideTheirLifetime) {
    // "sneaky" reads a's texture without declaring it: a was released after p2, its last declared user.
    addLoggedPass("p1", [](PassBuilder& b, Handles& h) { h.a = b.create("a", kColor); });
    addLoggedPass("p2", [this](PassBuilder& b, Handles& h) {
        h.a = b.read(graph.find("a"));
        b.sideEffect();
    });
    const ResourceHandle a = graph.find("a");
    graph.addPass<Handles>(
        "sneaky", [](PassBuilder& b, Handles&) { b.sideEffect(); },
        [a](const PassResources& r, const Handles&) { (void)r.texture(a); });
    EXPECT_THROW(graph.execute(), std::logic_error);
}

// Per-pass timing brackets exactly the passes that run.
class RecordingTimer final : public PassTimer {
public:
    void begin(std::string_view pass) override { events.push_back("begin " + std::string(pass)); }
    void end(std::string_view pass) override { events.push_back("end " + std::string(pass)); }
    std::vector<std::string> events;
};

TEST_F(FrameGraphTest, TimesEveryPassThatRuns) {
    addLoggedPass("culled", [](PassBuilder& b, Handles& h) { h.a = b.create("a", kColor); });
    addLoggedPass("kept", [](PassBuilder& b, Handles&) { b.sideEffect(); });
    RecordingTimer timer;
    graph.execute(&timer);
    EXPECT_EQ(timer.events, (std::vector<std::string>{"begin kept", "end kept"}));
}

}  // namespace
}  // namespace nimbus::gpu
