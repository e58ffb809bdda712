// composeRects (render/compose_pass.cpp): compose's scissor rects tile what it composes (the
// layer's cover, or the whole viewport) exactly once, the edge variant only over the edge rect.
#include "passes.h"

#include <gtest/gtest.h>

#include <vector>

namespace nimbus::render {
namespace {

// How many rects cover each pixel of a `size` viewport, and how many of them take the edge variant.
struct Coverage {
    std::vector<int> count, edges;
};

Coverage cover(glm::ivec2 size, const std::vector<std::pair<glm::ivec4, bool>>& rects) {
    Coverage c{std::vector<int>(static_cast<std::size_t>(size.x * size.y), 0), std::vector<int>(static_cast<std::size_t>(size.x * size.y), 0)};
    for (const auto& [r, edges] : rects)
        for (int y = r.y; y < r.y + r.w; ++y)
            for (int x = r.x; x < r.x + r.z; ++x) {
                EXPECT_TRUE(x >= 0 && y >= 0 && x < size.x && y < size.y) << "rect " << r.x << "," << r.y << " leaves the viewport";
                ++c.count[static_cast<std::size_t>(y * size.x + x)];
                c.edges[static_cast<std::size_t>(y * size.x + x)] += edges ? 1 : 0;
            }
    return c;
}

bool inside(glm::ivec4 r, int x, int y) { return x >= r.x && y >= r.y && x < r.x + r.z && y < r.y + r.w; }

TEST(ComposeRects, TileTheCoverOnceAndTheEdgeRectWithTheEdgeVariant) {
    const glm::ivec2 size(40, 30);
    const glm::ivec4 coverRect(5, 4, 20, 18), edgeRect(15, 10, 20, 8);  // the edge rect reaches past the cover
    const Coverage c = cover(size, composeRects(size, coverRect, edgeRect));
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = static_cast<std::size_t>(y * size.x + x);
            EXPECT_EQ(c.count[i], inside(coverRect, x, y) ? 1 : 0) << x << "," << y;
            EXPECT_EQ(c.edges[i], inside(coverRect, x, y) && inside(edgeRect, x, y) ? 1 : 0) << x << "," << y;
        }
}

TEST(ComposeRects, WithoutEdgesOneRectOverTheCover) {
    const glm::ivec2 size(40, 30);
    EXPECT_EQ(composeRects(size, {0, 0, 40, 30}, glm::ivec4(0)), (std::vector<std::pair<glm::ivec4, bool>>{{{0, 0, 40, 30}, false}}));
    EXPECT_EQ(composeRects(size, {3, 4, 5, 6}, glm::ivec4(0)), (std::vector<std::pair<glm::ivec4, bool>>{{{3, 4, 5, 6}, false}}));
    EXPECT_EQ(composeRects(size, {3, 4, 5, 6}, {20, 20, 5, 5}), (std::vector<std::pair<glm::ivec4, bool>>{{{3, 4, 5, 6}, false}}))
        << "an edge rect outside the cover: the cover alone";
}

}  // namespace
}  // namespace nimbus::render
