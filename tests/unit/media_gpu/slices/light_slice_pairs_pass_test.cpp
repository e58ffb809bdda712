// Tests plugins/participating_media/core/src/slices/light_slice_pairs_pass.cpp: every plane of every
// view lands in its pair layer beside its predecessor, and nothing else changes. That the readers
// interpolate from them as before is judged on scenes (their images did not move by a bit).
#include <gtest/gtest.h>

#include <vector>

#include "nimbus/gpu/context.h"
#include "nimbus/gpu/texture_pool.h"
#include "slices/light_slice_pairs_pass.h"

namespace nimbus::media {
namespace {

constexpr int kResolution = 5;

// Plane k of view v at texel t: distinct everywhere, so a value in the wrong place shows.
float planeValue(int view, int k, int texel) { return 1000.0f * static_cast<float>(view + 1) + 10.0f * static_cast<float>(k) + 0.01f * static_cast<float>(texel); }

TEST(LightSlicePairsPass, EachPlaneSitsBesideItsPredecessor) {
    const auto context = gpu::Context::create({.debug = gpu::ContextDesc::Debug::Off});
    // A view of 16 planes, one of 6 (a layer not filled), one of 20 (two draws).
    std::vector<SliceView> views(3);
    views[0].slices = 16;
    views[0].firstLayer = 0;
    views[1].slices = 6;
    views[1].firstLayer = 4;
    views[2].slices = 20;
    views[2].firstLayer = 6;
    const int packedLayers = 11;
    std::vector<glm::vec4> packed(static_cast<std::size_t>(kResolution * kResolution * packedLayers), glm::vec4(-1.0f));
    for (std::size_t v = 0; v < views.size(); ++v)
        for (int k = 0; k < views[v].slices; ++k)
            for (int t = 0; t < kResolution * kResolution; ++t)
                packed[static_cast<std::size_t>((views[v].firstLayer + k / 4) * kResolution * kResolution + t)][k % 4] =
                    planeValue(static_cast<int>(v), k, t);
    const gpu::Texture input({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32F, .width = kResolution, .height = kResolution, .depth = packedLayers});
    glTextureSubImage3D(input.id(), 0, 0, 0, 0, kResolution, kResolution, packedLayers, GL_RGBA, GL_FLOAT, packed.data());

    gpu::TexturePool pool;
    gpu::FrameGraph graph(pool);
    LightSlicePairsPass pass;
    const gpu::ResourceHandle pairs = pass.add(graph, views, kResolution, graph.importTexture("packed", input));
    graph.extract(pairs);
    graph.compile();
    graph.execute();
    const gpu::Texture* out = graph.extracted(pairs);
    ASSERT_NE(out, nullptr);
    const int layers = out->desc().depth;
    EXPECT_EQ(layers, 2 * 6 + 10);
    std::vector<glm::vec4> got(static_cast<std::size_t>(kResolution * kResolution * layers));
    glGetTextureImage(out->id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(got.size() * sizeof(glm::vec4)), got.data());
    for (std::size_t v = 0; v < views.size(); ++v)
        for (int k = 0; k < views[v].slices; ++k)
            for (int t = 0; t < kResolution * kResolution; ++t) {
                const glm::vec4 texel = got[static_cast<std::size_t>((2 * views[v].firstLayer + k / 2) * kResolution * kResolution + t)];
                const glm::vec2 ends = k % 2 == 0 ? glm::vec2(texel.x, texel.y) : glm::vec2(texel.z, texel.w);
                const float before = k == 0 ? 0.0f : planeValue(static_cast<int>(v), k - 1, t);
                EXPECT_EQ(ends.x, before) << "view " << v << " plane " << k << " texel " << t;
                EXPECT_EQ(ends.y, planeValue(static_cast<int>(v), k, t)) << "view " << v << " plane " << k << " texel " << t;
            }
    pool.release(out);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace nimbus::media
