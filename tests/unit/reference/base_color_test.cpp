// Tests plugins/participating_media/reference/src/base_color.cpp: factor × sRGB-decoded texture.
#include "base_color.h"

#include <gtest/gtest.h>

#include "nimbus/assets/image_io.h"

namespace nimbus::media::reference {
namespace {

// A 2×2 image: top row black, white; bottom row (sRGB 128), (sRGB 64).
assets::Scene texturedScene(assets::Wrap wrap, assets::Filter mag) {
    assets::Scene scene;
    assets::Image image;
    image.width = 2;
    image.height = 2;
    image.rgba8 = {0, 0, 0, 255, 255, 255, 255, 255, 128, 128, 128, 255, 64, 64, 64, 255};
    scene.images.push_back(image);
    assets::Texture texture;
    texture.image = 0;
    texture.wrapS = texture.wrapT = wrap;
    texture.magFilter = mag;
    scene.textures.push_back(texture);
    assets::Material material;
    material.baseColorFactor = {0.5f, 1.0f, 0.25f, 1.0f};
    material.baseColorTexture = 0;
    scene.materials.push_back(material);
    return scene;
}

double decode(int v) { return assets::srgbDecode(static_cast<float>(v) / 255.0f); }

TEST(BaseColor, TexelCentresNearestAndBilinearInLinearLight) {
    const assets::Scene scene = texturedScene(assets::Wrap::ClampToEdge, assets::Filter::Linear);
    const BaseColorSampler sampler(scene);
    EXPECT_NEAR(sampler.sampleTexture(0, {0.75, 0.25}).x, 1.0, 1e-7);          // a texel centre: white
    EXPECT_NEAR(sampler.sampleTexture(0, {0.25, 0.75}).x, decode(128), 1e-7);  // row 1 is v = 0.75
    // Halfway between the two bottom texels: the mean of the DECODED values.
    EXPECT_NEAR(sampler.sampleTexture(0, {0.5, 0.75}).x, 0.5 * (decode(128) + decode(64)), 1e-7);
    EXPECT_NEAR(sampler.sampleTexture(0, {0.0, 0.25}).x, 0.0, 1e-7);  // clamped at the edge
    const assets::Scene nearestScene = texturedScene(assets::Wrap::ClampToEdge, assets::Filter::Nearest);
    EXPECT_NEAR(BaseColorSampler(nearestScene).sampleTexture(0, {0.6, 0.7}).x, decode(64), 1e-7);
}

TEST(BaseColor, WrapModes) {
    const assets::Scene repeat = texturedScene(assets::Wrap::Repeat, assets::Filter::Nearest);
    const assets::Scene mirror = texturedScene(assets::Wrap::MirroredRepeat, assets::Filter::Nearest);
    EXPECT_NEAR(BaseColorSampler(repeat).sampleTexture(0, {1.75, 0.25}).x, 1.0, 1e-7);   // = u 0.75
    EXPECT_NEAR(BaseColorSampler(repeat).sampleTexture(0, {-0.25, 0.25}).x, 1.0, 1e-7);  // = u 0.75
    EXPECT_NEAR(BaseColorSampler(mirror).sampleTexture(0, {1.25, 0.25}).x, 1.0, 1e-7);   // mirrored: u 0.75
    EXPECT_NEAR(BaseColorSampler(mirror).sampleTexture(0, {1.75, 0.25}).x, 0.0, 1e-7);   // mirrored: u 0.25
}

TEST(BaseColor, FactorTimesTextureAndDefaults) {
    const assets::Scene scene = texturedScene(assets::Wrap::ClampToEdge, assets::Filter::Linear);
    const BaseColorSampler sampler(scene);
    raycast::MeshHit hit;
    hit.material = 0;
    hit.hasTexcoord0 = true;
    hit.texcoord0 = {0.75, 0.25};
    const glm::dvec3 c = sampler.at(hit);
    EXPECT_NEAR(c.x, 0.5, 1e-7);
    EXPECT_NEAR(c.y, 1.0, 1e-7);
    EXPECT_NEAR(c.z, 0.25, 1e-7);
    hit.material = -1;  // glTF default material: white
    EXPECT_EQ(sampler.at(hit), glm::dvec3(1.0));
}

}  // namespace
}  // namespace nimbus::media::reference
