// loadScene on real third-party files (Khronos Box, tinygltf models) and on our own scenes:
// what a loaded Scene holds.
#include <gtest/gtest.h>

#include "asset_test_util.h"
#include "nimbus/assets/scene.h"

namespace nimbus::assets {
namespace {

using test::dataPath;

TEST(GltfLoader, KhronosBoxHasItsCountsMaterialAndHierarchy) {
    const Scene scene = loadScene(dataPath("khronos/Box/Box.gltf"));
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.meshes[0].primitives.size(), 1u);
    const Primitive& p = scene.meshes[0].primitives[0];
    EXPECT_EQ(p.positions.size(), 24u);  // the file has normals: vertices are kept as written
    EXPECT_EQ(p.normals.size(), 24u);
    EXPECT_EQ(p.indices.size(), 36u);
    EXPECT_TRUE(p.texcoords0.empty());
    EXPECT_EQ(p.material, 0);
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_NEAR(scene.materials[0].baseColorFactor.r, 0.8f, 1e-6f);
    EXPECT_EQ(scene.materials[0].baseColorFactor.g, 0.0f);
    EXPECT_EQ(scene.materials[0].baseColorFactor.b, 0.0f);
    EXPECT_EQ(scene.materials[0].baseColorFactor.a, 1.0f);
    EXPECT_FALSE(scene.materials[0].baseColorTexture.present());
    EXPECT_EQ(scene.materials[0].metallicFactor, 1.0f);  // glTF's defaults: the file gives only baseColorFactor
    EXPECT_EQ(scene.materials[0].roughnessFactor, 1.0f);
    EXPECT_EQ(scene.materials[0].alphaMode, AlphaMode::Opaque);
    EXPECT_FALSE(scene.materials[0].doubleSided);
    EXPECT_TRUE(scene.environment.defaultAmbient);  // no lights and no NIMBUS root object
    EXPECT_EQ(scene.environment.ambient, glm::vec3(kDefaultAmbient));
    EXPECT_EQ(p.boundsMin, glm::vec3(-0.5f));
    EXPECT_EQ(p.boundsMax, glm::vec3(0.5f));

    ASSERT_EQ(scene.nodes.size(), 2u);
    EXPECT_TRUE(scene.nodes[0].hasMatrix);
    EXPECT_EQ(scene.nodes[0].matrix[1][2], -1.0);  // column 1, row 2 of the Y-up rotation
    EXPECT_EQ(scene.nodes[1].parent, 0);
    EXPECT_EQ(scene.nodes[1].mesh, 0);
    EXPECT_EQ(scene.rootNodes, std::vector<int>{0});
    EXPECT_NE(scene.document, nullptr);
    EXPECT_EQ(scene.displayName(), dataPath("khronos/Box/Box.gltf").string());
}

TEST(GltfLoader, CubeBaseColorTextureDecodesWithOpenImageIo) {
    const Scene scene = loadScene(dataPath("tinygltf/Cube/Cube.gltf"));
    ASSERT_EQ(scene.materials.size(), 1u);
    const Material& m = scene.materials[0];
    ASSERT_EQ(m.baseColorTexture.texture, 0);
    EXPECT_EQ(m.baseColorTexture.texCoord, 0);
    EXPECT_EQ(m.metallicRoughnessTexture.texture, 1);
    const Texture& t = scene.textures[0];
    ASSERT_EQ(t.image, 0);
    EXPECT_EQ(t.wrapS, Wrap::Repeat);  // the file's sampler is {}: glTF defaults
    EXPECT_EQ(t.minFilter, Filter::Linear);
    EXPECT_TRUE(t.mipmaps);

    ASSERT_EQ(scene.images.size(), 2u);
    const Image& img = scene.images[0];
    EXPECT_EQ(img.width, 512);
    EXPECT_EQ(img.height, 512);
    ASSERT_EQ(img.rgba8.size(), 512u * 512u * 4u);
    auto texel = [&](int x, int y) {
        const std::size_t i = (static_cast<std::size_t>(y) * 512 + static_cast<std::size_t>(x)) * 4;
        return glm::ivec4(img.rgba8[i], img.rgba8[i + 1], img.rgba8[i + 2], img.rgba8[i + 3]);
    };
    // Reference values read with oiiotool from Cube_BaseColor.png (sRGB-encoded, as stored).
    EXPECT_EQ(texel(0, 0), glm::ivec4(214, 200, 180, 255));
    EXPECT_EQ(texel(256, 256), glm::ivec4(214, 202, 181, 255));
    EXPECT_EQ(texel(511, 511), glm::ivec4(221, 209, 189, 255));
    // The metallic-roughness image is RGB: alpha is added as 255.
    EXPECT_EQ(scene.images[1].rgba8[3], 255);

    const Primitive& p = scene.meshes[0].primitives[0];
    EXPECT_EQ(p.texcoords0.size(), p.positions.size());
    EXPECT_EQ(p.indices.size(), 36u);
}

TEST(GltfLoader, GlbFilesLoad) {
    const Scene box = loadScene(dataPath("tinygltf/box01.glb"));
    ASSERT_EQ(box.meshes.size(), 1u);
    EXPECT_EQ(box.meshes[0].primitives[0].positions.size(), 32u);
    EXPECT_EQ(box.meshes[0].primitives[0].indices.size(), 36u);

    const Scene zeroBin = loadScene(dataPath("tinygltf/regression/zero-sized-bin-chunk-issue-440.glb"));
    ASSERT_EQ(zeroBin.materials.size(), 1u);
    EXPECT_TRUE(zeroBin.materials[0].doubleSided);
    EXPECT_NEAR(zeroBin.materials[0].baseColorFactor.g, 0.9f, 1e-6f);
    EXPECT_EQ(zeroBin.meshes[0].primitives[0].indices.size(), 3u);
}

TEST(GltfLoader, ContainerIsChosenByContentNotExtension) {
    const Scene glb = loadScene(dataPath("scenes/triangle.glb"));
    const Scene named = loadScene(dataPath("scenes/triangle_glb_named.gltf"));
    ASSERT_EQ(named.meshes.size(), 1u);
    EXPECT_EQ(named.meshes[0].primitives[0].positions, glb.meshes[0].primitives[0].positions);
}

TEST(GltfLoader, SparseMorphTargetGlbLoadsWithMorphTargetsIgnored) {
    const Scene scene = loadScene(dataPath("tinygltf/SparseMorphTargets-issue280/singleBlendshapeCube_sparse.glb"));
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].primitives[0].indices.size(), 36u);
    EXPECT_EQ(scene.meshes[0].primitives[0].positions.size(), 24u);
}

TEST(GltfLoader, ImageUrisWithSpacesResolve) {
    for (const char* file : {"tinygltf/CubeImageUriSpaces/CubeImageUriSpaces.gltf",
                             "tinygltf/CubeImageUriSpaces/CubeImageUriMultipleSpaces.gltf"}) {
        SCOPED_TRACE(file);
        const Scene scene = loadScene(dataPath(file));
        ASSERT_EQ(scene.images.size(), 1u);
        EXPECT_EQ(scene.images[0].width, 2);
        EXPECT_EQ(scene.images[0].height, 2);
        EXPECT_EQ(scene.textures[0].wrapS, Wrap::ClampToEdge);
        EXPECT_EQ(scene.textures[0].wrapT, Wrap::ClampToEdge);
    }
}

TEST(GltfLoader, TinyGltfExtensionRegressionsLoad) {
    const Scene issue97 = loadScene(dataPath("tinygltf/Extensions-issue97/test.gltf"));
    ASSERT_EQ(issue97.materials.size(), 1u);
    EXPECT_EQ(issue97.materials[0].name, "WHITE");
    EXPECT_EQ(issue97.meshes[0].primitives[0].indices.size(), 3u);

    const Scene issue261 = loadScene(dataPath("tinygltf/Extensions-overwrite-issue261/issue-261.gltf"));
    ASSERT_EQ(issue261.cameras.size(), 1u);
    EXPECT_NEAR(issue261.cameras[0].yfov, 0.9272952079772949, 1e-12);
    EXPECT_NEAR(issue261.cameras[0].zfar, 1000.0, 1e-9);
    ASSERT_EQ(issue261.lights.size(), 1u);
    EXPECT_EQ(issue261.lights[0].type, LightType::Point);
    EXPECT_EQ(issue261.lights[0].intensity, 1000.0f);
    EXPECT_EQ(issue261.nodes[2].light, 0);
    EXPECT_TRUE(issue261.nodes[0].extensions.contains("NV_Iray"));
    EXPECT_EQ(issue261.nodes[1].extensions["NV_Iray"]["material="], 3);
    EXPECT_TRUE(issue261.extensions.contains("NV_MDL"));
    EXPECT_TRUE(issue261.extensions.contains("KHR_lights_punctual"));

    const Scene textransform = loadScene(dataPath("tinygltf/Cube-texture-ext/Cube-textransform.gltf"));
    EXPECT_FALSE(textransform.meshes.empty());
}

TEST(GltfLoader, TextureTransformIsOneAffineMap) {
    // Cube-textransform's metallicRoughnessTexture: offset (0, 1), rotation π/2, scale 0.5:
    // uv' = offset + R(π/2)·S·uv = (−0.5 v, 1 + 0.5 u); its emissive texture flips v: (u, 1 − v).
    const Scene scene = loadScene(dataPath("tinygltf/Cube-texture-ext/Cube-textransform.gltf"));
    const TextureRef& mr = scene.materials[1].metallicRoughnessTexture;
    const glm::dvec2 a = mr.transform({0.2, 0.6});
    EXPECT_NEAR(a.x, -0.3, 1e-6);
    EXPECT_NEAR(a.y, 1.1, 1e-6);
    const glm::dvec2 b = scene.materials[0].emissiveTexture.transform({0.2, 0.6});
    EXPECT_NEAR(b.x, 0.2, 1e-7);
    EXPECT_NEAR(b.y, 0.4, 1e-7);
    EXPECT_FALSE(scene.materials[1].baseColorTexture.transform({0.2, 0.6}) != glm::dvec2(0.2, 0.6));  // no transform: identity
}

TEST(GltfLoader, SkinnedRegressionLoadsWithItsAnimation) {
    const Scene scene = loadScene(dataPath("tinygltf/regression/unassigned-skeleton.gltf"));
    ASSERT_EQ(scene.animations.size(), 1u);
    ASSERT_EQ(scene.animations[0].channels.size(), 2u);
    EXPECT_EQ(scene.animations[0].channels[0].node, 2);
    EXPECT_EQ(scene.animations[0].channels[0].path, AnimationPath::Rotation);
    EXPECT_EQ(scene.animations[0].channels[0].times.size(), 165u);
    EXPECT_EQ(scene.animations[0].channels[1].path, AnimationPath::Scale);
    EXPECT_EQ(scene.nodes[2].parent, 1);
    EXPECT_EQ(scene.rootNodes, (std::vector<int>{0, 1, 3}));
}

TEST(GltfLoader, CamerasLightsAndEnvironmentAreRead) {
    const Scene scene = loadScene(dataPath("scenes/lights_cameras.gltf"));
    ASSERT_EQ(scene.cameras.size(), 2u);
    EXPECT_EQ(scene.cameras[0].name, "WideCam");
    EXPECT_EQ(scene.cameras[0].projection, Projection::Perspective);
    EXPECT_EQ(scene.cameras[0].yfov, 1.0);
    EXPECT_EQ(scene.cameras[0].znear, 0.1);
    EXPECT_EQ(scene.cameras[0].zfar, 100.0);
    EXPECT_EQ(scene.cameras[0].aspectRatio, 1.5);
    EXPECT_EQ(scene.cameras[1].projection, Projection::Orthographic);
    EXPECT_EQ(scene.cameras[1].xmag, 2.0);
    EXPECT_EQ(scene.cameras[1].ymag, 3.0);
    EXPECT_EQ(scene.cameras[1].znear, 0.0);
    EXPECT_EQ(scene.cameras[1].zfar, 50.0);

    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.lights[0].name, "Sun");
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    EXPECT_EQ(scene.lights[0].color, glm::vec3(1.0f, 0.9f, 0.8f));
    EXPECT_EQ(scene.lights[0].intensity, 3.0f);
    EXPECT_EQ(scene.lights[1].type, LightType::Point);
    EXPECT_EQ(scene.lights[1].color, glm::vec3(1.0f));  // spec default
    EXPECT_EQ(scene.lights[1].range, 20.0);
    EXPECT_EQ(scene.lights[2].type, LightType::Spot);
    EXPECT_EQ(scene.lights[2].range, 0.0);  // absent: infinite
    EXPECT_EQ(scene.lights[2].innerConeAngle, 0.2);
    EXPECT_EQ(scene.lights[2].outerConeAngle, 0.6);
    EXPECT_EQ(scene.nodes[3].light, 0);
    EXPECT_EQ(scene.nodes[5].light, 2);
    EXPECT_EQ(scene.nodes[0].light, -1);

    EXPECT_EQ(scene.environment.background, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(scene.environment.ambient, glm::vec3(0.01f, 0.02f, 0.03f));
    EXPECT_EQ(scene.environment.scattering, Scattering::Multiple) << "the default model";
    // Other tools' data under the root object's extras is kept as written.
    EXPECT_EQ(scene.extensions[kMediaExtension]["extras"]["quality"], "another tool's data");
    EXPECT_EQ(scene.rootNodes, (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(GltfLoader, NodeExtensionsAreKeptExactlyAsWritten) {
    const Scene scene = loadScene(dataPath("scenes/lights_cameras.gltf"));
    const nlohmann::json& ext = scene.nodes[5].extensions;
    ASSERT_TRUE(ext.contains(kMediaExtension));
    const nlohmann::json& media = ext[kMediaExtension];
    EXPECT_TRUE(media["medium"]["extinction"].is_number_integer());  // 2 stays an integer
    EXPECT_TRUE(media["medium"]["g"].is_number_float());
    EXPECT_EQ(media["medium"]["g"].get<double>(), 0.25);
    EXPECT_TRUE(media["emitter"].is_object());  // empty objects and arrays survive
    EXPECT_TRUE(media["emitter"].empty());
    EXPECT_TRUE(media["tags"].is_array());
    EXPECT_EQ(media["big"].get<std::int64_t>(), 5000000000LL);  // beyond 32 bits
    EXPECT_EQ(ext["KHR_lights_punctual"]["light"], 2);
    EXPECT_TRUE(scene.nodes[0].extensions.is_object());
    EXPECT_TRUE(scene.nodes[0].extensions.empty());
}

TEST(GltfLoader, PlainFileWithoutLightsGetsTheDefaultAmbientOnBlack) {
    const Scene scene = loadScene(dataPath("khronos/Box/Box.gltf"));
    EXPECT_EQ(scene.environment.background, glm::vec3(0.0f));
    EXPECT_EQ(scene.environment.ambient, glm::vec3(kDefaultAmbient));  // docs/scene-format.md §4
    EXPECT_TRUE(scene.environment.defaultAmbient);
    EXPECT_TRUE(scene.extensions.is_object());
    EXPECT_TRUE(scene.lights.empty());
    EXPECT_TRUE(scene.cameras.empty());
}

TEST(GltfLoader, LightsOrOurRootObjectKeepTheAmbientAsWritten) {
    // lights_cameras.gltf has lights and writes its ambient: that one, no default.
    const Scene lit = loadScene(dataPath("scenes/lights_cameras.gltf"));
    EXPECT_FALSE(lit.environment.defaultAmbient);
    EXPECT_EQ(lit.environment.ambient, glm::vec3(0.01f, 0.02f, 0.03f));
    // A glTF file with lights and no NIMBUS object (tinygltf's issue-261 has a point light): none either.
    const Scene plain = loadScene(dataPath("tinygltf/Extensions-overwrite-issue261/issue-261.gltf"));
    EXPECT_FALSE(plain.environment.defaultAmbient);
    EXPECT_EQ(plain.environment.ambient, glm::vec3(0.0f));
}

}  // namespace
}  // namespace nimbus::assets
