// Tests plugins/participating_media/core/src/slices/light_slice_intervals_pass.cpp: every interval of
// every view holds the planes at its ends and either side of them, 0 before the near plane and the
// last plane's past the last, and nothing else changes; a crop's near plane extends planes 1 and 2.
// How the readers interpolate between them is judged on scenes (the seam band).
#include <gtest/gtest.h>

#include <vector>

#include "nimbus/gpu/context.h"
#include "nimbus/gpu/texture_pool.h"
#include "slices/light_slice_intervals_pass.h"

namespace nimbus::media {
namespace {

constexpr int kResolution = 5;

// Plane k of view v at texel t: distinct everywhere, so a value in the wrong place shows.
float planeValue(int view, int k, int texel) { return 1000.0f * static_cast<float>(view + 1) + 10.0f * static_cast<float>(k) + 0.01f * static_cast<float>(texel); }

TEST(LightSliceIntervalsPass, EachIntervalHoldsItsEndsAndTheirNeighbours) {
    const auto context = gpu::Context::create({.debug = gpu::ContextDesc::Debug::Off});
    // A view of 16 planes, one of 6 (a layer not filled), a crop of 20 (three draws).
    std::vector<SliceView> views(3);
    views[0].slices = 16;
    views[0].firstLayer = 0;
    views[1].slices = 6;
    views[1].firstLayer = 4;
    views[2].slices = 20;
    views[2].firstLayer = 6;
    views[2].seedView = 0;
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
    LightSliceIntervalsPass pass;
    const gpu::ResourceHandle pairs = pass.add(graph, views, kResolution, graph.importTexture("packed", input));
    graph.extract(pairs);
    graph.compile();
    graph.execute();
    const gpu::Texture* out = graph.extracted(pairs);
    ASSERT_NE(out, nullptr);
    const int layers = out->desc().depth;
    EXPECT_EQ(layers, 4 * 6 + 20);
    std::vector<glm::vec4> got(static_cast<std::size_t>(kResolution * kResolution * layers));
    glGetTextureImage(out->id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(got.size() * sizeof(glm::vec4)), got.data());
    for (std::size_t v = 0; v < views.size(); ++v) {
        const int planes = views[v].slices;
        for (int t = 0; t < kResolution * kResolution; ++t) {
            // Plane p's τ: slice p − 1 as packed; the near plane's and those before it 0, or for the
            // crop its near plane in line with planes 1 and 2.
            const auto tau = [&](int p) {
                if (p > planes) p = planes;
                if (p == 0 && views[v].seedView >= 0) return 2.0f * planeValue(static_cast<int>(v), 0, t) - planeValue(static_cast<int>(v), 1, t);
                return p <= 0 ? 0.0f : planeValue(static_cast<int>(v), p - 1, t);
            };
            for (int k = 0; k < planes; ++k) {
                const glm::vec4 texel = got[static_cast<std::size_t>((4 * views[v].firstLayer + k) * kResolution * kResolution + t)];
                EXPECT_EQ(texel, glm::vec4(tau(k - 1), tau(k), tau(k + 1), tau(k + 2))) << "view " << v << " interval " << k << " texel " << t;
            }
        }
    }
    pool.release(out);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace nimbus::media
