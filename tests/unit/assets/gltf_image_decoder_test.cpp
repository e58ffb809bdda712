// Images decoded with OpenImageIO into RGBA8: grey, grey + alpha, RGB, 16-bit, from files, data
// URIs and buffer views; samplers mapped to Texture settings.
#include <gtest/gtest.h>

#include "asset_test_util.h"
#include "nimbus/assets/scene.h"

namespace nimbus::assets {
namespace {

glm::ivec4 texel(const Image& img, int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) * 4;
    return {img.rgba8[i], img.rgba8[i + 1], img.rgba8[i + 2], img.rgba8[i + 3]};
}

class ImageDecoding : public ::testing::Test {
protected:
    static void SetUpTestSuite() { scene_ = new Scene(loadScene(test::dataPath("scenes/images.gltf"))); }
    static void TearDownTestSuite() {
        delete scene_;
        scene_ = nullptr;
    }
    static const Image& image(std::size_t i) { return scene_->images.at(i); }
    static Scene* scene_;
};
Scene* ImageDecoding::scene_ = nullptr;

TEST_F(ImageDecoding, AllImagesAreTwoByTwoRgba8) {
    ASSERT_EQ(scene_->images.size(), 6u);
    for (const Image& img : scene_->images) {
        EXPECT_EQ(img.width, 2);
        EXPECT_EQ(img.height, 2);
        EXPECT_EQ(img.rgba8.size(), 16u);
    }
}

TEST_F(ImageDecoding, GreyIsExpandedWithOpaqueAlpha) {
    EXPECT_EQ(texel(image(0), 1, 0), glm::ivec4(200, 200, 200, 255));
    EXPECT_EQ(texel(image(0), 0, 1), glm::ivec4(30, 30, 30, 255));  // row 0 is the top row
}

TEST_F(ImageDecoding, GreyAlphaKeepsAlpha) {
    EXPECT_EQ(texel(image(1), 1, 0), glm::ivec4(200, 200, 200, 201));
    EXPECT_EQ(texel(image(1), 0, 1), glm::ivec4(30, 30, 30, 31));
}

TEST_F(ImageDecoding, RgbGetsOpaqueAlpha) {
    EXPECT_EQ(texel(image(2), 1, 0), glm::ivec4(4, 5, 6, 255));
    EXPECT_EQ(texel(image(2), 0, 1), glm::ivec4(7, 8, 9, 255));
}

TEST_F(ImageDecoding, SixteenBitIsRescaledToEightBit) {
    EXPECT_EQ(texel(image(3), 1, 0), glm::ivec4(255, 128, 0, 255));
    EXPECT_EQ(texel(image(3), 0, 1), glm::ivec4(0, 255, 0, 0));
    EXPECT_EQ(texel(image(3), 1, 1), glm::ivec4(1, 2, 3, 4));
}

TEST_F(ImageDecoding, DataUriAndBufferViewImagesDecodeLikeTheFile) {
    EXPECT_EQ(image(4).rgba8, image(2).rgba8);
    EXPECT_EQ(image(5).rgba8, image(2).rgba8);
    EXPECT_EQ(image(5).name, "in a buffer view");
    EXPECT_EQ(image(0).name, "images/grey.png");  // unnamed external images are named by their uri
}

TEST_F(ImageDecoding, SamplersMapToTextureSettings) {
    ASSERT_EQ(scene_->textures.size(), 6u);
    const Texture& t = scene_->textures[0];
    EXPECT_EQ(t.image, 0);
    EXPECT_EQ(t.magFilter, Filter::Nearest);
    EXPECT_EQ(t.minFilter, Filter::Nearest);  // NEAREST_MIPMAP_LINEAR
    EXPECT_TRUE(t.mipmaps);
    EXPECT_EQ(t.wrapS, Wrap::ClampToEdge);
    EXPECT_EQ(t.wrapT, Wrap::MirroredRepeat);
    const Texture& plain = scene_->textures[5];  // no sampler: glTF defaults
    EXPECT_EQ(plain.wrapS, Wrap::Repeat);
    EXPECT_EQ(plain.wrapT, Wrap::Repeat);
    EXPECT_EQ(plain.magFilter, Filter::Linear);
    EXPECT_TRUE(plain.mipmaps);
}

}  // namespace
}  // namespace nimbus::assets
