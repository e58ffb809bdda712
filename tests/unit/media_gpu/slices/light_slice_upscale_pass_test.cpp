// Tests plugins/participating_media/core/src/slices/light_slice_upscale_pass.cpp: a view drawn
// small lands in its layers of the slice array bilinear with its own edge clamped, drawn with
// gl_Layer and one layer a draw, and views drawn at the array's resolution are left as they were.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "nimbus/gpu/context.h"
#include "nimbus/gpu/texture_pool.h"
#include "slices/light_slice_upscale_pass.h"

namespace nimbus::media {
namespace {

constexpr int kResolution = 8, kSmallSide = 4;

// The small array's texel (x, y) of layer l, channel c: distinct, and linear in neither x nor y,
// so a misplaced or unclamped sample shows.
float smallValue(int l, int x, int y, int c) { return 100.0f * static_cast<float>(l) + 10.0f * static_cast<float>(x * x) + static_cast<float>(y) + 0.25f * static_cast<float>(c); }

// A linear blit's texel of a view of side `own`: bilinear at (dst + ½)·own/resolution, the view's
// edge clamped.
float expected(int l, int own, int x, int y, int c) {
    const auto at = [&](double s, int& i0, double& f) {
        const double t = s - 0.5;
        i0 = static_cast<int>(std::floor(t));
        f = t - i0;
    };
    int x0, y0;
    double fx, fy;
    at((x + 0.5) * own / kResolution, x0, fx);
    at((y + 0.5) * own / kResolution, y0, fy);
    const auto v = [&](int i, int j) { return static_cast<double>(smallValue(l, std::clamp(i, 0, own - 1), std::clamp(j, 0, own - 1), c)); };
    return static_cast<float>((1 - fy) * ((1 - fx) * v(x0, y0) + fx * v(x0 + 1, y0)) + fy * ((1 - fx) * v(x0, y0 + 1) + fx * v(x0 + 1, y0 + 1)));
}

void expectUpscaled(bool layered) {
    const auto context = gpu::Context::create({.debug = gpu::ContextDesc::Debug::Off});
    if (layered && !LightSliceUpscalePass::supported()) GTEST_SKIP() << "no ARB_shader_viewport_layer_array";
    // A view at the array's resolution (layers 0–1), a small one of side 4 (layers 2–3; small
    // layers 0–1) and a smaller one of side 3 in the small array's corner (layer 4; small layer 2).
    std::vector<SliceView> views(3);
    views[0].slices = 8;
    views[0].firstLayer = 0;
    views[1].slices = 8;
    views[1].firstLayer = 2;
    views[1].resolution = 4;
    views[2].slices = 3;
    views[2].firstLayer = 4;
    views[2].resolution = 3;
    const int layers = 5, smallLayers = 3;
    std::vector<glm::vec4> small(static_cast<std::size_t>(kSmallSide * kSmallSide * smallLayers));
    for (int l = 0; l < smallLayers; ++l)
        for (int y = 0; y < kSmallSide; ++y)
            for (int x = 0; x < kSmallSide; ++x)
                for (int c = 0; c < 4; ++c) small[static_cast<std::size_t>((l * kSmallSide + y) * kSmallSide + x)][c] = smallValue(l, x, y, c);
    const gpu::Texture smallTexture({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32F, .width = kSmallSide, .height = kSmallSide, .depth = smallLayers});
    glTextureSubImage3D(smallTexture.id(), 0, 0, 0, 0, kSmallSide, kSmallSide, smallLayers, GL_RGBA, GL_FLOAT, small.data());
    const std::vector<glm::vec4> before(static_cast<std::size_t>(kResolution * kResolution * layers), glm::vec4(-7.0f));
    const gpu::Texture slices({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32F, .width = kResolution, .height = kResolution, .depth = layers});
    glTextureSubImage3D(slices.id(), 0, 0, 0, 0, kResolution, kResolution, layers, GL_RGBA, GL_FLOAT, before.data());

    gpu::TexturePool pool;
    gpu::FrameGraph graph(pool);
    LightSliceUpscalePass pass(layered);
    const LightSlicePass::Output drawn{graph.importTexture("slices", slices), graph.importTexture("small", smallTexture),
                                       {.smallFirstLayer = {-1, 0, 2}, .size = kSmallSide, .layers = smallLayers}};
    const gpu::ResourceHandle out = pass.add(graph, views, kResolution, drawn);
    graph.extract(out);
    graph.compile();
    graph.execute();
    std::vector<glm::vec4> got(before.size());
    glGetTextureImage(slices.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(got.size() * sizeof(glm::vec4)), got.data());
    const auto texel = [&](int layer, int x, int y) { return got[static_cast<std::size_t>((layer * kResolution + y) * kResolution + x)]; };
    for (int y = 0; y < kResolution; ++y)
        for (int x = 0; x < kResolution; ++x) {
            for (int layer = 0; layer < 2; ++layer) EXPECT_EQ(texel(layer, x, y), glm::vec4(-7.0f)) << "a full-size view is left alone";
            for (int c = 0; c < 4; ++c) {
                for (int a = 0; a < 2; ++a)
                    EXPECT_NEAR(texel(2 + a, x, y)[c], expected(a, 4, x, y, c), 1e-3) << "view 1 layer " << a << " at " << x << "," << y;
                EXPECT_NEAR(texel(4, x, y)[c], expected(2, 3, x, y, c), 1e-3) << "view 2 at " << x << "," << y;
            }
        }
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(LightSliceUpscalePass, DrawnWithGlLayerEachSmallViewLandsInItsLayersBilinear) { expectUpscaled(true); }
TEST(LightSliceUpscalePass, OneLayerADrawEachSmallViewLandsInItsLayersBilinear) { expectUpscaled(false); }

}  // namespace
}  // namespace nimbus::media
