#include "nimbus/ecs/resources.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "expect_error.h"

namespace nimbus::ecs {
namespace {

struct Settings {
    int quality = 1;
    std::string mode = "particles";
};

struct Gravity {
    double g;
};

TEST(Resources, InsertGetTryGetContainsRemove) {
    Resources r;
    EXPECT_FALSE(r.contains<Settings>());
    EXPECT_EQ(r.tryGet<Settings>(), nullptr);
    Settings& s = r.insert<Settings>();
    EXPECT_EQ(s.quality, 1);
    s.quality = 3;
    EXPECT_TRUE(r.contains<Settings>());
    EXPECT_EQ(&r.get<Settings>(), &s);
    EXPECT_EQ(r.tryGet<Settings>(), &s);
    EXPECT_EQ(r.insert<Gravity>(9.81).g, 9.81);  // brace-initialised aggregate
    EXPECT_EQ(r.size(), 2u);
    EXPECT_TRUE(r.remove<Settings>());
    EXPECT_FALSE(r.remove<Settings>());
    EXPECT_FALSE(r.contains<Settings>());
    EXPECT_EQ(r.size(), 1u);
    const Resources& cr = r;
    EXPECT_EQ(cr.get<Gravity>().g, 9.81);
}

TEST(Resources, InsertReplacesTheValue) {
    Resources r;
    r.insert<Settings>(Settings{2, "blocks"});
    r.insert<Settings>(Settings{5, "sheets"});
    EXPECT_EQ(r.get<Settings>().quality, 5);
    EXPECT_EQ(r.get<Settings>().mode, "sheets");
    EXPECT_EQ(r.size(), 1u);
}

TEST(Resources, MissingResourceErrorNamesTheType) {
    Resources r;
    EXPECT_TRUE(test::throwsLogicError([&] { (void)r.get<Settings>(); }, "Settings"));
    const Resources& cr = r;
    EXPECT_TRUE(test::throwsLogicError([&] { (void)cr.get<Gravity>(); }, "Gravity is missing"));
}

TEST(Resources, DestroyedInReverseOrderOfFirstInsertion) {
    std::vector<int> log;
    struct Logs {
        std::vector<int>* log;
        int id;
        ~Logs() { log->push_back(id); }
    };
    struct First : Logs {};
    struct Second : Logs {};
    struct Third : Logs {};
    {
        Resources r;
        r.insert<First>(First{{&log, 1}});
        r.insert<Second>(Second{{&log, 2}});
        r.insert<Third>(Third{{&log, 3}});
        log.clear();  // the temporaries above logged too
        r.insert<First>(First{{&log, 1}});  // replacing keeps First's place (and destroys the old one)
        log.clear();
    }
    EXPECT_EQ(log, (std::vector<int>{3, 2, 1}));
}

}  // namespace
}  // namespace nimbus::ecs
