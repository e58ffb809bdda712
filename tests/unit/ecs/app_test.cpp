#include "nimbus/ecs/app.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "expect_error.h"

namespace nimbus::ecs {
namespace {

struct Position {
    double x = 0.0;
};
struct Velocity {
    double dx = 0.0;
};
struct Gravity {
    double g = -9.81;
};

// Counts its builds in a shared counter; the counter outlives the App.
class CountingPlugin final : public Plugin {
public:
    explicit CountingPlugin(int* builds, std::string name = "counting") : builds_(builds), name_(std::move(name)) {}
    std::string_view name() const override { return name_; }
    void build(App&) override { ++*builds_; }

private:
    int* builds_;
    std::string name_;
};

// A typical plugin: components, a resource, a startup system and an update system on a view.
class MotionPlugin final : public Plugin {
public:
    std::string_view name() const override { return "motion"; }
    void build(App& app) override {
        app.registerComponent<Position>("Position");
        app.registerComponent<Velocity>("Velocity");
        app.insertResource<Gravity>();
        app.addSystem({.name = "motion.spawn", .phase = phases::kStartup}, [](World& w) {
            for (int i = 0; i < 3; ++i) {
                const Entity e = w.create();
                w.emplace<Position>(e, 0.0);
                w.emplace<Velocity>(e, double(i));
            }
        });
        app.addSystem({.name = "motion.integrate"}, [](World& w) {
            const double dt = w.resource<FrameInfo>().timeStep;
            w.view<Position, const Velocity>().each([&](Position& p, const Velocity& v) { p.x += v.dx * dt; });
        });
    }
};

// Depends on MotionPlugin and adds it itself.
class TrailsPlugin final : public Plugin {
public:
    std::string_view name() const override { return "trails"; }
    void build(App& app) override {
        app.addPlugin<MotionPlugin>();
        app.addSystem({.name = "trails.follow", .after = {"motion.integrate"}}, [](World&) {});
    }
};

class ThrowingPlugin final : public Plugin {
public:
    std::string_view name() const override { return "throwing"; }
    void build(App&) override { throw std::runtime_error("cannot build"); }
};

TEST(App, PluginAddedTwiceBuildsOnce) {
    int builds = 0;
    App app;
    EXPECT_TRUE(app.addPlugin<CountingPlugin>(&builds));
    EXPECT_FALSE(app.addPlugin<CountingPlugin>(&builds));
    EXPECT_FALSE(app.addPlugin(std::make_unique<CountingPlugin>(&builds)));
    EXPECT_EQ(builds, 1);
    EXPECT_TRUE(app.hasPlugin("counting"));
    EXPECT_TRUE(app.addPlugin<CountingPlugin>(&builds, "other"));  // identity is the name
    EXPECT_EQ(builds, 2);
}

TEST(App, SharedDependencyBuildsOnce) {
    App app;
    app.addPlugin<TrailsPlugin>();
    EXPECT_FALSE(app.addPlugin<MotionPlugin>());
    EXPECT_TRUE(app.hasPlugin("motion"));
    app.update();
    EXPECT_EQ(app.world().count<Position>(), 3u);  // one spawn system, run once
}

TEST(App, PluginWhoseBuildThrowsIsNotRecorded) {
    App app;
    EXPECT_THROW(app.addPlugin<ThrowingPlugin>(), std::runtime_error);
    EXPECT_FALSE(app.hasPlugin("throwing"));
    EXPECT_THROW(app.addPlugin(nullptr), std::logic_error);
}

TEST(App, UpdateRunsPhasesAndStartupOnlyFirst) {
    App app;
    std::vector<std::string> ran;
    for (const char* phase : {phases::kPresent, phases::kRender, phases::kPrepare, phases::kSimulate, phases::kStartup})
        app.addSystem({.name = phase, .phase = phase}, [&ran, phase](World&) { ran.push_back(phase); });
    EXPECT_EQ(app.frame(), 0u);
    app.update();
    app.update();
    EXPECT_EQ(app.frame(), 2u);
    EXPECT_EQ(ran, (std::vector<std::string>{"Startup", "Simulate", "Prepare", "Render", "Present", "Simulate",
                                             "Prepare", "Render", "Present"}));
    ran.clear();
    app.runPhase(phases::kRender);
    EXPECT_EQ(ran, (std::vector<std::string>{"Render"}));
    EXPECT_EQ(app.frame(), 2u);  // a lone phase is not a frame
    ran.clear();
    app.redraw();
    EXPECT_EQ(ran, (std::vector<std::string>{"Prepare", "Render", "Present"}));
    EXPECT_EQ(app.frame(), 2u);  // nor is a redraw: no simulation, no clock
}

TEST(App, UpdateUpToAPhaseStopsThereAndAdvancesTheClock) {
    App app;
    std::vector<std::string> ran;
    for (const char* phase : {phases::kPresent, phases::kRender, phases::kPrepare, phases::kSimulate, phases::kStartup})
        app.addSystem({.name = phase, .phase = phase}, [&ran, phase](World&) { ran.push_back(phase); });
    app.update(phases::kSimulate);
    app.update(phases::kSimulate);
    EXPECT_EQ(app.frame(), 2u);
    EXPECT_EQ(app.world().resource<FrameInfo>().index, 1u);
    EXPECT_EQ(ran, (std::vector<std::string>{"Startup", "Simulate", "Simulate"}));
    EXPECT_THROW(app.update("NoSuchPhase"), std::logic_error);
}

TEST(App, SystemRegisteredTwiceRunsOnce) {
    App app;
    int runs = 0;
    EXPECT_TRUE(app.addSystem({.name = "tick"}, [&](World&) { ++runs; }));
    EXPECT_FALSE(app.addSystem({.name = "tick"}, [&](World&) { ++runs; }));
    app.update();
    EXPECT_EQ(runs, 1);
}

TEST(App, FrameInfoAdvancesByTheFixedStep) {
    App app(AppDesc{.fixedTimeStep = 0.25});
    std::vector<FrameInfo> seen;
    app.addSystem({.name = "watch"}, [&](World& w) { seen.push_back(w.resource<FrameInfo>()); });
    for (int i = 0; i < 4; ++i) app.update();
    ASSERT_EQ(seen.size(), 4u);
    for (std::uint64_t i = 0; i < 4; ++i) {
        EXPECT_EQ(seen[i].index, i);
        EXPECT_DOUBLE_EQ(seen[i].time, 0.25 * double(i));
        EXPECT_EQ(seen[i].timeStep, 0.25);
    }
    EXPECT_THROW(App(AppDesc{.fixedTimeStep = 0.0}), std::logic_error);
    EXPECT_THROW(App(AppDesc{.fixedTimeStep = std::nan("")}), std::logic_error);
}

TEST(App, PluginSystemsIterateViewsAndReadResources) {
    App app(AppDesc{.fixedTimeStep = 0.5});
    app.addPlugin<MotionPlugin>();
    for (int i = 0; i < 4; ++i) app.update();
    std::vector<double> xs;
    app.world().view<const Position, const Velocity>().each(
        [&](const Position& p, const Velocity& v) { EXPECT_DOUBLE_EQ(p.x, v.dx * 0.5 * 4); });
    EXPECT_EQ(app.world().count<Position>(), 3u);
    EXPECT_EQ(app.resource<Gravity>().g, -9.81);
    ASSERT_NE(app.components().find("Velocity"), nullptr);
    EXPECT_EQ(app.scheduler().systemOrder(phases::kSimulate), (std::vector<std::string>{"motion.integrate"}));
}

TEST(App, ResourcesThroughTheApp) {
    App app;
    EXPECT_FALSE(app.hasResource<Gravity>());
    EXPECT_EQ(app.tryResource<Gravity>(), nullptr);
    EXPECT_TRUE(test::throwsLogicError([&] { (void)app.resource<Gravity>(); }, "Gravity"));
    app.insertResource<Gravity>(Gravity{-1.62});
    EXPECT_TRUE(app.hasResource<Gravity>());
    EXPECT_EQ(app.resource<Gravity>().g, -1.62);
    EXPECT_EQ(&app.world().resource<Gravity>(), app.tryResource<Gravity>());
    EXPECT_TRUE(app.hasResource<FrameInfo>());  // the App's own
}

TEST(App, RegisterComponentTwiceIsHarmless) {
    App app;
    EXPECT_TRUE(app.registerComponent<Position>("Position"));
    EXPECT_FALSE(app.registerComponent<Position>("Position"));
    EXPECT_EQ(app.components().all().size(), 1u);
}

// Systems may point into the World and plugins, resources into plugins: tear-down goes systems,
// World, plugins.
TEST(App, TearDownOrderIsSystemsThenWorldThenPlugins) {
    auto log = std::make_shared<std::vector<std::string>>();
    struct Logs {
        std::shared_ptr<std::vector<std::string>> log;
        std::string name;
        ~Logs() {
            if (log) log->push_back(name);
        }
    };
    class LoggingPlugin final : public Plugin {
    public:
        explicit LoggingPlugin(std::shared_ptr<std::vector<std::string>> l) : logs_{std::move(l), "plugin"} {}
        std::string_view name() const override { return "logging"; }
        void build(App& app) override {
            app.insertResource<Logs>(Logs{logs_.log, "resource"});
            auto captured = std::make_shared<Logs>(Logs{logs_.log, "system"});
            app.addSystem({.name = "logging.noop"}, [captured](World&) {});
        }

    private:
        Logs logs_;
    };
    {
        App app;
        app.addPlugin<LoggingPlugin>(log);
        log->clear();  // temporaries made while building logged too
    }
    EXPECT_EQ(*log, (std::vector<std::string>{"system", "resource", "plugin"}));
}

}  // namespace
}  // namespace nimbus::ecs
