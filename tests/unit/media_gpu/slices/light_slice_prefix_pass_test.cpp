// Tests plugins/participating_media/core/src/slices/light_slice_prefix_pass.cpp: each view's planes
// are the running sums of its slabs, and a crop's start from its seed, the whole view's optical
// depth at the crop's first plane where the crop's texel lies in the whole view.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "nimbus/gpu/context.h"
#include "nimbus/gpu/texture_pool.h"
#include "nimbus/gpu/view.h"
#include "slices/light_slice_prefix_pass.h"

namespace nimbus::media {
namespace {

constexpr int kResolution = 8, kSlices = 8;

gpu::LightView orthographic(const glm::vec2& half, const glm::vec2& mid, float depthNear, float depthFar) {
    gpu::LightView v;
    v.view = glm::translate(glm::mat4(1.0f), glm::vec3(-mid, 0.0f));
    v.viewProjection = gpu::reversedOrthographic(half.x, half.y, depthNear, depthFar) * v.view;
    v.depthNear = depthNear;
    v.depthFar = depthFar;
    v.halfExtent = half;
    return v;
}

// The whole view's slab j at uv: linear across, so its bilinear lookup anywhere inside is exact.
float wholeSlab(int j, const glm::vec2& uv) { return static_cast<float>(1 + j) * (1.0f + 2.0f * uv.x + uv.y); }
constexpr float kCropSlab = 0.25f;

TEST(LightSlicePrefixPass, ACropStartsFromTheWholeViewsDepthAtItsFirstPlane) {
    const auto context = gpu::Context::create({.debug = gpu::ContextDesc::Debug::Off});
    // The whole view over depths 0..8; the crop a quarter of it across, its first plane at 3.5:
    // half way through the whole view's slab 3.
    std::vector<SliceView> views(2);
    views[0] = {.view = orthographic(glm::vec2(4.0f), glm::vec2(0.0f), 0.0f, 8.0f), .slices = kSlices, .firstLayer = 0};
    const float spacing = 4.0f / static_cast<float>(kSlices - 1);
    views[1] = {.view = orthographic(glm::vec2(2.0f), glm::vec2(1.0f, -1.0f), 3.5f - spacing, 7.5f), .slices = kSlices, .firstLayer = 2, .seedView = 0};
    std::vector<float> slabs(static_cast<std::size_t>(kResolution * kResolution * 2 * kSlices), 0.0f);
    for (int j = 0; j < kSlices; ++j)
        for (int y = 0; y < kResolution; ++y)
            for (int x = 0; x < kResolution; ++x) {
                const glm::vec2 uv((static_cast<float>(x) + 0.5f) / kResolution, (static_cast<float>(y) + 0.5f) / kResolution);
                slabs[static_cast<std::size_t>((j * kResolution + y) * kResolution + x)] = wholeSlab(j, uv);
                // The crop's first slab holds no particle: the seed stands for it.
                slabs[static_cast<std::size_t>(((kSlices + j) * kResolution + y) * kResolution + x)] = j == 0 ? 0.0f : kCropSlab;
            }
    const gpu::Texture input({.target = GL_TEXTURE_2D_ARRAY, .format = GL_R32F, .width = kResolution, .height = kResolution, .depth = 2 * kSlices});
    glTextureSubImage3D(input.id(), 0, 0, 0, 0, kResolution, kResolution, 2 * kSlices, GL_RED, GL_FLOAT, slabs.data());

    gpu::TexturePool pool;
    gpu::FrameGraph graph(pool);
    LightSlicePrefixPass pass;
    const gpu::ResourceHandle sums = pass.add(graph, views, kResolution, graph.importTexture("slabs", input));
    graph.extract(sums);
    graph.compile();
    graph.execute();
    const gpu::Texture* out = graph.extracted(sums);
    ASSERT_NE(out, nullptr);
    std::vector<glm::vec4> got(static_cast<std::size_t>(kResolution * kResolution * out->desc().depth));
    glGetTextureImage(out->id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(got.size() * sizeof(glm::vec4)), got.data());
    const auto plane = [&](const SliceView& v, int k, int x, int y) {
        return got[static_cast<std::size_t>(((v.firstLayer + k / 4) * kResolution + y) * kResolution + x)][k % 4];
    };
    for (int y = 0; y < kResolution; ++y)
        for (int x = 0; x < kResolution; ++x) {
            const glm::vec2 uv((static_cast<float>(x) + 0.5f) / kResolution, (static_cast<float>(y) + 0.5f) / kResolution);
            float sum = 0.0f;
            for (int k = 0; k < kSlices; ++k) {
                sum += wholeSlab(k, uv);
                EXPECT_NEAR(plane(views[0], k, x, y), sum, 1e-4f * sum) << "whole view, plane " << k;
            }
            // The crop's texel centre, through the views' own matrices, in the whole view.
            const glm::vec4 point = glm::inverse(views[1].view.viewProjection) * glm::vec4(2.0f * uv - 1.0f, 0.5f, 1.0f);
            const glm::vec4 clip = views[0].view.viewProjection * point;
            const glm::vec2 wholeUv = 0.5f * glm::vec2(clip) / clip.w + 0.5f;
            const float seed = wholeSlab(0, wholeUv) + wholeSlab(1, wholeUv) + wholeSlab(2, wholeUv) + 0.5f * wholeSlab(3, wholeUv);
            for (int k = 0; k < kSlices; ++k)
                EXPECT_NEAR(plane(views[1], k, x, y), seed + kCropSlab * static_cast<float>(k), 2e-3f * seed) << "crop, plane " << k << " texel " << x << ", " << y;
        }
    pool.release(out);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace nimbus::media
