// Tests engine/assets/src/material_sampling.cpp: factor × texture × COLOR_0, sRGB-decoded colours
// and linear alpha and metallic-roughness, KHR_texture_transform, TEXCOORD_1, the default material.
#include "nimbus/assets/material_sampling.h"

#include <gtest/gtest.h>

#include "nimbus/assets/image_io.h"

namespace nimbus::assets {
namespace {

// A 2×2 image: top row black, white; bottom row (sRGB 128), (sRGB 64); alphas 255, 0, 128, 64.
Scene texturedScene(Wrap wrap, Filter mag) {
    Scene scene;
    Image image;
    image.width = 2;
    image.height = 2;
    image.rgba8 = {0, 0, 0, 255, 255, 255, 255, 0, 128, 128, 128, 128, 64, 64, 64, 64};
    scene.images.push_back(image);
    Texture texture;
    texture.image = 0;
    texture.wrapS = texture.wrapT = wrap;
    texture.magFilter = mag;
    scene.textures.push_back(texture);
    Material material;
    material.baseColorFactor = {0.5f, 1.0f, 0.25f, 1.0f};
    material.baseColorTexture.texture = 0;
    scene.materials.push_back(material);
    return scene;
}

double decode(int v) { return srgbDecode(static_cast<float>(v) / 255.0f); }

TEST(MaterialSampling, TexelCentresNearestAndBilinearInLinearLight) {
    const Scene scene = texturedScene(Wrap::ClampToEdge, Filter::Linear);
    const MaterialSampler sampler(scene);
    EXPECT_NEAR(sampler.sampleTexture(0, {0.75, 0.25}, true).x, 1.0, 1e-7);          // a texel centre: white
    EXPECT_NEAR(sampler.sampleTexture(0, {0.25, 0.75}, true).x, decode(128), 1e-7);  // row 1 is v = 0.75
    // Halfway between the two bottom texels: the mean of the DECODED values; alpha is never decoded.
    EXPECT_NEAR(sampler.sampleTexture(0, {0.5, 0.75}, true).x, 0.5 * (decode(128) + decode(64)), 1e-7);
    EXPECT_NEAR(sampler.sampleTexture(0, {0.5, 0.75}, true).w, 0.5 * (128.0 + 64.0) / 255.0, 1e-7);
    EXPECT_NEAR(sampler.sampleTexture(0, {0.5, 0.75}, false).x, 0.5 * (128.0 + 64.0) / 255.0, 1e-7);  // linear data
    EXPECT_NEAR(sampler.sampleTexture(0, {0.0, 0.25}, true).x, 0.0, 1e-7);  // clamped at the edge
    const Scene nearestScene = texturedScene(Wrap::ClampToEdge, Filter::Nearest);
    EXPECT_NEAR(MaterialSampler(nearestScene).sampleTexture(0, {0.6, 0.7}, true).x, decode(64), 1e-7);
}

TEST(MaterialSampling, WrapModes) {
    const Scene repeat = texturedScene(Wrap::Repeat, Filter::Nearest);
    const Scene mirror = texturedScene(Wrap::MirroredRepeat, Filter::Nearest);
    EXPECT_NEAR(MaterialSampler(repeat).sampleTexture(0, {1.75, 0.25}, true).x, 1.0, 1e-7);   // = u 0.75
    EXPECT_NEAR(MaterialSampler(repeat).sampleTexture(0, {-0.25, 0.25}, true).x, 1.0, 1e-7);  // = u 0.75
    EXPECT_NEAR(MaterialSampler(mirror).sampleTexture(0, {1.25, 0.25}, true).x, 1.0, 1e-7);   // mirrored: u 0.75
    EXPECT_NEAR(MaterialSampler(mirror).sampleTexture(0, {1.75, 0.25}, true).x, 0.0, 1e-7);   // mirrored: u 0.25
}

TEST(MaterialSampling, FactorTimesTextureTimesVertexColour) {
    const Scene scene = texturedScene(Wrap::ClampToEdge, Filter::Linear);
    const MaterialSampler sampler(scene);
    SurfaceAttributes at;
    at.uv0 = {0.25, 0.75};                 // sRGB 128, alpha 128
    at.color = {0.5, 1.0, 1.0, 0.5};
    const MaterialSample s = sampler.sample(0, at);
    EXPECT_NEAR(s.baseColor.x, 0.5 * decode(128) * 0.5, 1e-7);
    EXPECT_NEAR(s.baseColor.y, 1.0 * decode(128), 1e-7);
    EXPECT_NEAR(s.baseColor.z, 0.25 * decode(128), 1e-7);
    EXPECT_NEAR(s.baseColor.w, 128.0 / 255.0 * 0.5, 1e-7);
    EXPECT_NEAR(sampler.alpha(0, at), s.baseColor.w, 1e-12);
    const MaterialSample d = sampler.sample(-1, at);  // glTF default material: white, metallic 1, roughness 1
    EXPECT_EQ(glm::dvec3(d.baseColor), glm::dvec3(0.5, 1.0, 1.0));  // COLOR_0 still applies
    EXPECT_EQ(d.metallic, 1.0);
    EXPECT_EQ(d.roughness, 1.0);
    EXPECT_EQ(d.emissive, glm::dvec3(0.0));
}

TEST(MaterialSampling, MetallicRoughnessEmissiveTransformAndSecondSet) {
    Scene scene = texturedScene(Wrap::ClampToEdge, Filter::Nearest);
    Material& m = scene.materials[0];
    m.baseColorTexture = {};
    m.metallicFactor = 0.5f;
    m.roughnessFactor = 0.8f;
    m.metallicRoughnessTexture.texture = 0;  // linear: roughness from g, metalness from b
    m.emissiveFactor = {2.0f, 1.0f, 0.0f};
    m.emissiveTexture.texture = 0;
    m.emissiveTexture.texCoord = 1;
    // KHR_texture_transform offset (0.5, 0): the texel right of where TEXCOORD_1 points.
    m.emissiveTexture.row0 = {1.0f, 0.0f, 0.5f};
    const MaterialSampler sampler(scene);
    SurfaceAttributes at;
    at.uv0 = {0.25, 0.75};  // sRGB 128 stored: 128/255 linear
    at.uv1 = {0.25, 0.25};  // + 0.5 in u: the white texel
    const MaterialSample s = sampler.sample(0, at);
    EXPECT_NEAR(s.metallic, 0.5 * 128.0 / 255.0, 1e-7);
    EXPECT_NEAR(s.roughness, 0.8 * 128.0 / 255.0, 1e-7);
    EXPECT_NEAR(s.emissive.x, 2.0, 1e-7);
    EXPECT_NEAR(s.emissive.y, 1.0, 1e-7);
}

}  // namespace
}  // namespace nimbus::assets
