#include "nimbus/ecs/paged_vector.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace nimbus::ecs {
namespace {

struct Counted {
    static inline int live = 0;
    int value = 0;
    explicit Counted(int v) : value(v) { ++live; }
    Counted(const Counted& o) : value(o.value) { ++live; }
    Counted& operator=(const Counted&) = default;
    ~Counted() { --live; }
};

TEST(PagedVector, GrowsAcrossPagesWithoutMovingElements) {
    PagedVector<std::uint64_t> v;
    const std::size_t n = 5 * PagedVector<std::uint64_t>::kPageSize + 3;
    v.emplace_back(0u);
    const std::uint64_t* first = &v[0];
    for (std::size_t i = 1; i < n; ++i) v.emplace_back(i);
    ASSERT_EQ(v.size(), n);
    EXPECT_EQ(&v[0], first);  // growth never relocates
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(v[i], i);
}

TEST(PagedVector, PopAndClearDestroyElements) {
    Counted::live = 0;
    {
        PagedVector<Counted> v;
        for (int i = 0; i < 1000; ++i) v.emplace_back(i);
        EXPECT_EQ(Counted::live, 1000);
        v.pop_back();
        EXPECT_EQ(Counted::live, 999);
        EXPECT_EQ(v.back().value, 998);
        v.clear();
        EXPECT_EQ(Counted::live, 0);
        EXPECT_TRUE(v.empty());
        v.emplace_back(5);
        EXPECT_EQ(v[0].value, 5);
    }
    EXPECT_EQ(Counted::live, 0);  // the destructor destroys what is left
}

TEST(PagedVector, MoveTransfersElements) {
    Counted::live = 0;
    PagedVector<Counted> a;
    for (int i = 0; i < 10; ++i) a.emplace_back(i);
    PagedVector<Counted> b(std::move(a));
    EXPECT_EQ(b.size(), 10u);
    EXPECT_EQ(b[9].value, 9);
    PagedVector<Counted> c;
    c.emplace_back(42);
    c = std::move(b);
    EXPECT_EQ(c.size(), 10u);
    EXPECT_EQ(Counted::live, 10);
    c.clear();
    EXPECT_EQ(Counted::live, 0);
}

TEST(PagedVector, BraceInitialisesAggregatesAndHonoursAlignment) {
    struct alignas(64) Wide {
        float a;
        std::string b;
    };
    PagedVector<Wide> v;
    for (int i = 0; i < 700; ++i) v.emplace_back(float(i), std::to_string(i));
    for (std::size_t i = 0; i < v.size(); ++i) {
        ASSERT_EQ(reinterpret_cast<std::uintptr_t>(&v[i]) % 64, 0u);
        ASSERT_EQ(v[i].b, std::to_string(i));
    }
}

}  // namespace
}  // namespace nimbus::ecs
