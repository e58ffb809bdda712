// Tests plugins/participating_media/core/src/planning/impostor_atlas.cpp: tile packing, block rectangles in
// a view, tile sizes.
#include "nimbus/media/impostor_atlas.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "block_test_clouds.h"
#include "nimbus/gpu/view.h"

namespace nimbus::media {
namespace {

bool overlap(const AtlasTile& a, const AtlasTile& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

void expectDisjointInside(const AtlasLayout& layout, int maxSize) {
    EXPECT_GE(layout.width, 1);
    EXPECT_GE(layout.height, 1);
    EXPECT_LE(layout.width, maxSize);
    EXPECT_LE(layout.height, maxSize);
    for (std::size_t i = 0; i < layout.tiles.size(); ++i) {
        const AtlasTile& t = layout.tiles[i];
        if (t.width == 0) continue;
        EXPECT_GE(t.x, 0);
        EXPECT_GE(t.y, 0);
        // Aligned, so the half-resolution lit atlas holds each tile's texels two by two, disjoint.
        EXPECT_EQ(t.x % kTileAlignment, 0) << "tile " << i;
        EXPECT_EQ(t.y % kTileAlignment, 0) << "tile " << i;
        EXPECT_LE(t.x + t.width, layout.width) << "tile " << i;
        EXPECT_LE(t.y + t.height, layout.height) << "tile " << i;
        for (std::size_t j = i + 1; j < layout.tiles.size(); ++j)
            EXPECT_FALSE(layout.tiles[j].width > 0 && overlap(t, layout.tiles[j])) << "tiles " << i << " and " << j;
    }
}

std::vector<glm::ivec2> randomSizes(std::size_t n, unsigned seed, int lo, int hi) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> side(lo, hi);
    std::vector<glm::ivec2> sizes(n);
    for (auto& s : sizes) s = glm::ivec2(side(rng), side(rng));
    return sizes;
}

TEST(ImpostorAtlas, TilesFitWithoutOverlapAtTheRequestedSizes) {
    for (unsigned seed : {1u, 2u, 3u}) {
        const auto sizes = randomSizes(40, seed, 4, 120);
        const AtlasLayout layout = packAtlas(sizes, 2048);
        EXPECT_EQ(layout.shrink, 1.0f);
        ASSERT_EQ(layout.tiles.size(), sizes.size());
        for (std::size_t i = 0; i < sizes.size(); ++i) {
            EXPECT_EQ(layout.tiles[i].width, sizes[i].x);
            EXPECT_EQ(layout.tiles[i].height, sizes[i].y);
        }
        expectDisjointInside(layout, 2048);
    }
}

TEST(ImpostorAtlas, ShrinksEveryTileByOneFactorWhenTheyDoNotFit) {
    // 100 tiles of 256² need 6.5M texels; a 1024² atlas holds 1M: they must shrink (to <= ~0.39).
    const std::vector<glm::ivec2> sizes(100, glm::ivec2(256));
    const AtlasLayout layout = packAtlas(sizes, 1024);
    EXPECT_LT(layout.shrink, 0.4f);
    EXPECT_GT(layout.shrink, 0.0f);
    const int expected = static_cast<int>(std::floor(256.0f * layout.shrink));
    for (const AtlasTile& t : layout.tiles) {
        EXPECT_EQ(t.width, expected);
        EXPECT_EQ(t.height, expected);
    }
    expectDisjointInside(layout, 1024);
    // Mixed sizes shrink proportionally (floor, at least one texel).
    const auto mixed = randomSizes(300, 7, 1, 256);
    const AtlasLayout m = packAtlas(mixed, 512);
    EXPECT_LT(m.shrink, 1.0f);
    for (std::size_t i = 0; i < mixed.size(); ++i) {
        EXPECT_EQ(m.tiles[i].width, std::max(1, static_cast<int>(std::floor(static_cast<float>(mixed[i].x) * m.shrink))));
        EXPECT_EQ(m.tiles[i].height, std::max(1, static_cast<int>(std::floor(static_cast<float>(mixed[i].y) * m.shrink))));
    }
    expectDisjointInside(m, 512);
}

TEST(ImpostorAtlas, ZeroSizeRequestsGetZeroTiles) {
    std::vector<glm::ivec2> sizes = {{16, 16}, {0, 0}, {32, 8}, {0, 0}, {0, 5}};
    const AtlasLayout layout = packAtlas(sizes, 256);
    EXPECT_EQ(layout.tiles[1].width, 0);
    EXPECT_EQ(layout.tiles[3].width, 0);
    EXPECT_EQ(layout.tiles[4].width, 0);
    EXPECT_EQ(layout.tiles[0].width, 16);
    EXPECT_EQ(layout.tiles[2].width, 32);
    expectDisjointInside(layout, 256);
    const AtlasLayout none = packAtlas(std::vector<glm::ivec2>(3, glm::ivec2(0)), 256);
    EXPECT_EQ(none.width, 1);
    EXPECT_EQ(none.height, 1);
    for (const AtlasTile& t : none.tiles) EXPECT_EQ(t.width, 0);
}

TEST(ImpostorAtlas, PackingIsDeterministic) {
    const auto sizes = randomSizes(64, 11, 4, 200);
    const AtlasLayout a = packAtlas(sizes, 1024), b = packAtlas(sizes, 1024);
    ASSERT_EQ(a.tiles.size(), b.tiles.size());
    EXPECT_EQ(a.shrink, b.shrink);
    for (std::size_t i = 0; i < a.tiles.size(); ++i) {
        EXPECT_EQ(a.tiles[i].x, b.tiles[i].x);
        EXPECT_EQ(a.tiles[i].y, b.tiles[i].y);
        EXPECT_EQ(a.tiles[i].width, b.tiles[i].width);
    }
}

// The camera view the media pass uses for a camera (origin = the eye, reversed Z).
ImpostorView cameraView(const gpu::View& v) {
    return ImpostorView{v.view, v.viewProjection, true, glm::vec3(0.0f), v.znear, glm::ivec2(v.width, v.height)};
}

// An orthographic light-style view looking along `dir` (origin-relative, as light views are).
ImpostorView orthographicView(const glm::dvec3& target, const glm::dvec3& dir, const glm::dvec3& origin, double half) {
    const glm::vec3 centre(target - origin);
    const glm::vec3 up = std::abs(dir.y) > 0.9 ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::mat4 view = glm::lookAt(centre - glm::vec3(dir) * 30.0f, centre, up);
    const glm::mat4 projection = gpu::reversedOrthographic(half, half, 0.1, 60.0);
    return ImpostorView{view, projection * view, false, glm::vec3(0.0f), 0.0f, glm::ivec2(256)};
}

// Checks that every sampled point on each block's bounding sphere that is in front of the near
// plane projects inside the block's rectangle (rectangles are clipped to the view).
void expectRectanglesHoldSpheres(const BlockPartition& p, const ImpostorView& view, const glm::dvec3& origin,
                                 int& checkedPoints) {
    const std::vector<BlockFootprint> footprints = blockFootprints(p, view, origin);
    ASSERT_EQ(footprints.size(), p.blocks.size());
    const glm::dmat4 vp(view.viewProjection), viewMatrix(view.view);
    for (std::size_t b = 0; b < p.blocks.size(); ++b) {
        const glm::vec4 r = footprints[b].rect;
        const Block& block = p.blocks[b];
        for (int i = 0; i < 24; ++i)
            for (int j = 0; j <= 12; ++j) {
                const double phi = 2.0 * 3.14159265358979 * i / 24.0, theta = 3.14159265358979 * j / 12.0;
                const glm::dvec3 onSphere = block.centre - origin +
                                            block.radius * glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                                      std::sin(theta) * std::sin(phi));
                if (view.perspective && -(viewMatrix * glm::dvec4(onSphere, 1.0)).z <= view.nearDepth) continue;
                const glm::dvec4 clip = vp * glm::dvec4(onSphere, 1.0);
                const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
                ASSERT_TRUE(std::isfinite(ndc.x) && std::isfinite(ndc.y));
                if (std::abs(ndc.x) > 1.0 || std::abs(ndc.y) > 1.0) continue;  // off-view: clipped away
                ++checkedPoints;
                EXPECT_TRUE(ndc.x >= r.x - 1e-5 && ndc.x <= r.z + 1e-5 && ndc.y >= r.y - 1e-5 && ndc.y <= r.w + 1e-5)
                    << "block " << b << " point (" << ndc.x << ", " << ndc.y << ") outside [" << r.x << ", " << r.y
                    << "] – [" << r.z << ", " << r.w << "]";
            }
    }
}

TEST(ImpostorAtlas, BlockRectanglesHoldEachBlocksProjectedSphere) {
    const ParticleSet set = test::blobCloud(500, 5);
    const BlockPartition p = partitionIntoBlocks(set, 0);
    int checked = 0;
    for (const glm::dvec3 eye : {glm::dvec3(0.0, 8.5, 12.5), glm::dvec3(-9.0, 2.0, 4.0), glm::dvec3(3.0, 14.0, 0.5)}) {
        const gpu::View v = test::makeView(test::lookAtCamera(eye, glm::dvec3(0.0, 4.0, 0.0)), 320, 180);
        expectRectanglesHoldSpheres(p, cameraView(v), v.origin, checked);
    }
    // Far from the world origin, relative to the camera as the renderer does it.
    ParticleSet far = set;
    for (auto& q : far.position) q += glm::dvec3(1e5, 0.0, -1e5);
    const BlockPartition pf = partitionIntoBlocks(far, 0);
    const gpu::View vf = test::makeView(test::lookAtCamera(glm::dvec3(1e5, 8.5, 12.5 - 1e5), glm::dvec3(1e5, 4.0, -1e5)), 320, 180);
    expectRectanglesHoldSpheres(pf, cameraView(vf), vf.origin, checked);
    // Orthographic light-style views.
    const glm::dvec3 origin(0.0, 8.5, 12.5);
    for (const glm::dvec3 dir : {glm::dvec3(0.35, -0.6, -0.72), glm::dvec3(0.0, -1.0, 0.0)})
        expectRectanglesHoldSpheres(p, orthographicView(glm::dvec3(0.0, 4.0, 0.0), glm::normalize(dir), origin, 7.0), origin, checked);
    EXPECT_GT(checked, 30000);  // the samples did land in the views
}

TEST(ImpostorAtlas, BlockCrossingTheNearPlaneCoversTheWholeView) {
    const ParticleSet set = test::blobCloud(100, 4);
    const BlockPartition p = partitionIntoBlocks(set, 1);  // one block: the whole cloud
    const Block& b = p.blocks.front();
    // Eye inside the block's sphere, looking at its centre and looking away: both cross the near plane.
    for (const glm::dvec3 target : {b.centre, b.centre + glm::dvec3(0.0, 0.0, 10.0)}) {
        const glm::dvec3 eye = b.centre + glm::dvec3(0.0, 0.0, 0.5 * b.radius);
        const gpu::View v = test::makeView(test::lookAtCamera(eye, target), 160, 90);
        EXPECT_EQ(blockFootprints(p, cameraView(v), v.origin).front().rect, glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f));
    }
    // Eye just outside the sphere, the sphere's front within the near distance: also the whole view.
    const glm::dvec3 eye = b.centre + glm::dvec3(0.0, 0.0, b.radius + 0.05);
    const gpu::View v = test::makeView(test::lookAtCamera(eye, b.centre, 0.7, 0.1), 160, 90);
    EXPECT_EQ(blockFootprints(p, cameraView(v), v.origin).front().rect, glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f));
}

TEST(ImpostorAtlas, BlocksBehindOrBesideTheViewGetZeroRectanglesAndTiles) {
    const ParticleSet set = test::blobCloud(100, 4);
    const BlockPartition p = partitionIntoBlocks(set, 1);
    const Block& b = p.blocks.front();
    const glm::dvec3 eye = b.centre + glm::dvec3(0.0, 0.0, b.radius + 20.0);
    // Behind the eye, and 70° off the view axis (outside the ±33° horizontal field of view).
    const double off = 70.0 * 3.14159265358979 / 180.0;
    for (const glm::dvec3 target : {eye + glm::dvec3(0.0, 0.0, 1.0), eye + glm::dvec3(std::sin(off), 0.0, -std::cos(off))}) {
        const gpu::View v = test::makeView(test::lookAtCamera(eye, target), 160, 90);
        const auto footprints = blockFootprints(p, cameraView(v), v.origin);
        EXPECT_EQ(footprints.front().rect, glm::vec4(0.0f));
        const auto sizes = tileSizes(footprints, glm::ivec2(160, 90), 0.5f);
        EXPECT_EQ(sizes.front(), glm::ivec2(0));
        EXPECT_EQ(packAtlas(sizes, 256).tiles.front().width, 0);
    }
}

TEST(ImpostorAtlas, TileSizesFollowCoveredPixelsTimesScaleClamped) {
    const glm::ivec2 viewport(320, 180);
    // Particles 10 px in radius: resolved at both scales here, so the tiles follow the scale.
    // A rectangle covering half the view's width and a quarter of its height: 160×45 pixels.
    const std::vector<BlockFootprint> footprints = {{glm::vec4(-0.5f, -0.25f, 0.5f, 0.25f), 10.0f},
                                                    {glm::vec4(0.0f), 10.0f},
                                                    {glm::vec4(0.0f, 0.0f, 0.001f, 0.001f), 10.0f},
                                                    {glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f), 10.0f}};
    const auto half = tileSizes(footprints, viewport, 0.5f);
    EXPECT_EQ(half[0], glm::ivec2(80, 23));   // ceil(160·0.5), ceil(45·0.5)
    EXPECT_EQ(half[1], glm::ivec2(0));        // empty
    EXPECT_EQ(half[2], glm::ivec2(4));        // at least 4 texels
    EXPECT_EQ(half[3], glm::ivec2(160, 90));
    const auto big = tileSizes(footprints, viewport, 4.0f);
    EXPECT_EQ(big[0], glm::ivec2(256, 180));  // at most 256
    EXPECT_EQ(big[3], glm::ivec2(256, 256));
}

TEST(ImpostorAtlas, BlocksOfUnresolvedParticlesGetOneTexelPerPixel) {
    const glm::ivec2 viewport(320, 180);
    // 7.9 px particles are 3.95 texels in radius at scale 0.5 (< kResolvedParticleTexels): per pixel.
    const std::vector<BlockFootprint> small = {{glm::vec4(-0.5f, -0.25f, 0.5f, 0.25f), 7.9f},
                                               {glm::vec4(0.0f, 0.0f, 4.0f / 320.0f, 4.0f / 180.0f), 0.2f}};
    const auto sizes = tileSizes(small, viewport, 0.5f);
    EXPECT_EQ(sizes[0], glm::ivec2(160, 45));
    EXPECT_EQ(sizes[1], glm::ivec2(2, 2));  // no minimum of 4: the texels stay on the pixels
    EXPECT_EQ(tileSizes({{small[0].rect, 8.1f}}, viewport, 0.5f).front(), glm::ivec2(80, 23));
    EXPECT_EQ(tileSizes(small, viewport, 2.0f).front(), glm::ivec2(256, 90));  // finer than a pixel stays so
}

TEST(ImpostorAtlas, BlocksOfAtMostOneLayerOfParticlesGetOneTexelPerPixel) {
    const glm::ivec2 viewport(320, 180);
    const glm::vec4 rect(-0.5f, -0.25f, 0.5f, 0.25f);  // 160×45 pixels
    EXPECT_EQ(tileSizes({{rect, 20.0f, 0.8f}}, viewport, 0.5f).front(), glm::ivec2(160, 45));
    EXPECT_EQ(tileSizes({{rect, 20.0f, 1.0f}}, viewport, 0.5f).front(), glm::ivec2(160, 45));
    EXPECT_EQ(tileSizes({{rect, 20.0f, 1.2f}}, viewport, 0.5f).front(), glm::ivec2(80, 23));
}

TEST(ImpostorAtlas, OverdrawCountsTheParticleDiscsOverTheRectangle) {
    // One particle alone: its disc covers less than its bounding square; a dense blob sums many.
    const gpu::View v = test::makeView(test::lookAtCamera(glm::dvec3(0.0, 0.0, 30.0), glm::dvec3(0.0)), 320, 180);
    ParticleSet one;
    one.push(glm::dvec3(0.0), 2.0f, 1.0f, Medium{});
    const auto lone = blockFootprints(partitionIntoBlocks(one, 1), cameraView(v), v.origin);
    EXPECT_GT(lone.front().overdraw, 0.3f);
    EXPECT_LE(lone.front().overdraw, 3.14159265f / 4.0f);
    const ParticleSet blob = test::blobCloud(2000, 5, glm::dvec3(0.0));
    const auto dense = blockFootprints(partitionIntoBlocks(blob, 1), cameraView(v), v.origin);
    EXPECT_GT(dense.front().overdraw, 2.0f);
}

TEST(ImpostorAtlas, FootprintsLieOnThePixelGridAndMeasureTheParticles) {
    const ParticleSet set = test::blobCloud(500, 5);
    const BlockPartition p = partitionIntoBlocks(set, 0);
    const gpu::View v = test::makeView(test::lookAtCamera(glm::dvec3(0.0, 8.5, 12.5), glm::dvec3(0.0, 4.0, 0.0)), 320, 180);
    const ImpostorView view = cameraView(v);
    const auto footprints = blockFootprints(p, view, v.origin);
    const glm::dmat4 viewMatrix(view.view);
    const double focalPixels = 0.5 * 180.0 / v.tanHalfFovY;
    int visible = 0;
    for (std::size_t b = 0; b < p.blocks.size(); ++b) {
        const glm::vec4 r = footprints[b].rect;
        if (r.z <= r.x) continue;
        ++visible;
        for (int k = 0; k < 4; ++k) {
            const float pixel = (r[k] * 0.5f + 0.5f) * (k % 2 == 0 ? 320.0f : 180.0f);
            EXPECT_NEAR(pixel, std::round(pixel), 1e-3f) << "block " << b << " edge " << k;
        }
        const double depth = -(viewMatrix * glm::dvec4(p.blocks[b].centre - v.origin, 1.0)).z;
        EXPECT_NEAR(footprints[b].particlePixels, p.blocks[b].meanParticleRadius * focalPixels / depth,
                    1e-3 * footprints[b].particlePixels);
    }
    EXPECT_GT(visible, 10);
}

}  // namespace
}  // namespace nimbus::media
