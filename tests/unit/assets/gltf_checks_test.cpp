// Refusals: every malformed file is refused with ONE InputError line naming the file, the object
// and the field (gltf_checks.h, gltf_container.h, and the data checks made while building).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "asset_test_util.h"

namespace nimbus::assets {
namespace {

using test::dataPath;
using test::isOneLine;
using test::refusalOf;

TEST(GltfChecks, EveryTinyGltfBoundsCheckingFileIsRefusedOnOneLine) {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dataPath("tinygltf/BoundsChecking"))) {
        if (entry.path().extension() != ".gltf") continue;
        ++files;
        SCOPED_TRACE(entry.path().string());
        const std::string message = refusalOf(entry.path());
        EXPECT_NE(message.find(entry.path().filename().string()), std::string::npos) << message;
        EXPECT_TRUE(isOneLine(message)) << message;
    }
    EXPECT_EQ(files, 4);
}

TEST(GltfChecks, BoundsCheckingFilesNameTheirDefect) {
    // The byteLength of 1e300 is a float, not an integer.
    EXPECT_NE(refusalOf(dataPath("tinygltf/BoundsChecking/integer-out-of-bounds.gltf")).find("bufferViews[0]: byteLength: must be an integer"),
              std::string::npos);
    EXPECT_NE(refusalOf(dataPath("tinygltf/BoundsChecking/invalid-buffer-index.gltf")).find("bufferViews[1]: buffer: index 1 is out of range"),
              std::string::npos);
    // These two also reference buffer 0 of an empty "buffers" array, which is found first.
    EXPECT_NE(refusalOf(dataPath("tinygltf/BoundsChecking/invalid-buffer-view-index.gltf")).find("bufferViews[0]: buffer: index 0 is out of range"),
              std::string::npos);
    EXPECT_NE(refusalOf(dataPath("tinygltf/BoundsChecking/invalid-primitive-indices.gltf")).find("bufferViews[0]: buffer: index 0 is out of range"),
              std::string::npos);
}

struct MalformedCase {
    const char* file;
    std::vector<const char*> expected;  // substrings of the message: object, field, problem
};

class Malformed : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(Malformed, IsRefusedNamingObjectAndField) {
    const MalformedCase& c = GetParam();
    const auto path = dataPath(std::string("malformed/") + c.file);
    const std::string message = refusalOf(path);
    EXPECT_TRUE(isOneLine(message)) << message;
    EXPECT_EQ(message.rfind(path.string(), 0), 0u) << "message must start with the file: " << message;
    for (const char* part : c.expected) EXPECT_NE(message.find(part), std::string::npos) << "missing \"" << part << "\" in: " << message;
}

INSTANTIATE_TEST_SUITE_P(
    GltfChecks, Malformed,
    ::testing::Values(
        MalformedCase{"nan_translation.gltf", {"animations[0]", "samplers[0].output", "value 1 is not finite"}},
        MalformedCase{"nan_position.gltf", {"meshes[0]", "primitives[0].attributes.POSITION", "vertex 1 is not finite"}},
        MalformedCase{"overflow_translation.gltf", {"JSON", "line 3", "1e400"}},
        MalformedCase{"negative_light_intensity.gltf", {"light \"Lamp\" (KHR_lights_punctual.lights[0])", "intensity", "-5", ">= 0"}},
        MalformedCase{"unknown_light_type.gltf", {"KHR_lights_punctual.lights[0]", "type", "unknown value \"area\""}},
        MalformedCase{"negative_light_range.gltf", {"KHR_lights_punctual.lights[0]", "range", "must be > 0"}},
        MalformedCase{"spot_cone_order.gltf", {"KHR_lights_punctual.lights[0]", "spot.innerConeAngle", "smaller than outerConeAngle"}},
        MalformedCase{"spot_cone_too_wide.gltf", {"KHR_lights_punctual.lights[0]", "spot.outerConeAngle", "out of range"}},
        MalformedCase{"light_index_out_of_range.gltf", {"node \"Tri\" (nodes[0])", "extensions.KHR_lights_punctual.light", "index 3"}},
        MalformedCase{"accessor_out_of_range.gltf", {"accessors[0]", "count", "only 36 bytes"}},
        MalformedCase{"accessor_absurd_count.gltf", {"accessors[0]", "count", "268435457"}},
        MalformedCase{"stride_too_small.gltf", {"accessors[0]", "bufferView", "byteStride 8 is smaller than the element size 12"}},
        MalformedCase{"index_out_of_range.gltf", {"meshes[0]", "primitives[0].indices", "value 7", "vertex count 3"}},
        MalformedCase{"position_not_vec3.gltf", {"meshes[0]", "primitives[0].attributes.POSITION", "VEC2 FLOAT", "expected VEC3 FLOAT"}},
        MalformedCase{"missing_buffer_file.gltf", {"buffers[0]", "uri", "no such file \"missing.bin\""}},
        MalformedCase{"missing_image_file.gltf", {"images[0]", "uri", "no such file \"no such image.png\""}},
        MalformedCase{"image_too_large.gltf", {"images[0]", "uri", "20000x1", "16384"}},
        MalformedCase{"image_not_decodable.gltf", {"image \"Garbage\" (images[0])", "uri", "not a PNG, JPEG or WebP"}},
        MalformedCase{"image_outside_folder.gltf", {"image \"Elsewhere\" (images[0])", "uri", "outside the glTF file's folder"}},
        MalformedCase{"truncated.glb", {"GLB container", "length", "truncated"}},
        MalformedCase{"glb_version_1.glb", {"GLB container", "version", "GLB version 1"}},
        MalformedCase{"empty.gltf", {"empty"}},
        MalformedCase{"node_cycle.gltf", {"children", "cycle", "nodes[0]", "nodes[1]", "nodes[2]"}},
        MalformedCase{"node_two_parents.gltf", {"node \"B\" (nodes[1])", "children[0]", "already has a parent", "node \"A\" (nodes[0])"}},
        MalformedCase{"node_own_child.gltf", {"node \"Tri\" (nodes[0])", "children[0]", "its own child"}},
        MalformedCase{"bad_background.gltf", {"NIMBUS_participating_media", "background", "3 numbers"}},
        MalformedCase{"negative_ambient.gltf", {"NIMBUS_participating_media", "ambient[1]", "-0.2"}},
        MalformedCase{"root_typo.gltf", {"root extension NIMBUS_participating_media", "ambeint", "unknown key"}},
        MalformedCase{"unknown_scattering.gltf", {"root extension NIMBUS_participating_media", "scattering", "\"double\""}},
        MalformedCase{"camera_zero_yfov.gltf", {"cameras[0]", "perspective.yfov", "(0, pi)"}},
        MalformedCase{"camera_zfar_before_znear.gltf", {"camera \"Cam\" (cameras[0])", "perspective.zfar", "greater than znear"}},
        MalformedCase{"camera_negative_znear.gltf", {"cameras[0]", "perspective.znear", "must be > 0"}},
        MalformedCase{"node_mesh_out_of_range.gltf", {"node \"Tri\" (nodes[0])", "mesh", "index 5 is out of range"}},
        MalformedCase{"translation_not_array.gltf", {"nodes[0]", "translation", "must be a JSON array"}},
        MalformedCase{"matrix_and_trs.gltf", {"nodes[0]", "matrix", "cannot be combined with scale"}},
        MalformedCase{"animation_times_decrease.gltf", {"animations[0]", "samplers[0].input", "strictly increase"}},
        MalformedCase{"animation_output_count.gltf", {"animations[0]", "samplers[0].output", "in-tangent"}},
        MalformedCase{"animation_unknown_interpolation.gltf", {"animations[0]", "samplers[0].interpolation", "\"SMOOTH\""}},
        MalformedCase{"unsupported_required_extension.gltf", {"extensionsRequired[0]", "KHR_draco_mesh_compression"}},
        MalformedCase{"bad_base64.gltf", {"buffers[0]", "uri", "invalid base64 character"}},
        MalformedCase{"buffer_length_mismatch.gltf", {"buffers[0]", "byteLength", "holds 36 bytes"}},
        MalformedCase{"texture_without_texcoord.gltf", {"meshes[0]", "attributes.TEXCOORD_0", "material \"Textured\" (materials[0])"}},
        MalformedCase{"base_color_out_of_range.gltf", {"materials[0]", "pbrMetallicRoughness.baseColorFactor[1]", "must be in [0.0, 1.0]"}},
        MalformedCase{"alpha_cutoff_negative.gltf", {"material \"Leaves\" (materials[0])", "alphaCutoff", "-0.5"}},
        MalformedCase{"emissive_texcoord_missing.gltf", {"meshes[0]", "attributes.TEXCOORD_1", "material \"Lamp\" (materials[0])", "emissiveTexture"}},
        MalformedCase{"color_wrong_type.gltf", {"mesh \"Painted\" (meshes[0])", "attributes.COLOR_0", "SCALAR FLOAT", "expected VEC3"}},
        MalformedCase{"alpha_blend.gltf", {"material \"Glass\" (materials[0])", "alphaMode", "BLEND is not supported"}},
        MalformedCase{"texture_transform_bad_scale.gltf", {"materials[0]", "baseColorTexture.extensions.KHR_texture_transform.scale", "2 numbers"}},
        MalformedCase{"gltf_version_1.gltf", {"asset", "version", "\"1.0\""}},
        MalformedCase{"syntax_error.gltf", {"JSON", "malformed JSON", "line 2"}}),
    [](const ::testing::TestParamInfo<MalformedCase>& param) {
        std::string name = param.param.file;
        for (char& ch : name)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        return name;
    });

TEST(GltfChecks, MissingFileIsRefused) {
    const std::string message = refusalOf(dataPath("malformed/does_not_exist.gltf"));
    EXPECT_NE(message.find("does_not_exist.gltf"), std::string::npos);
    EXPECT_NE(message.find("no such file"), std::string::npos);
}

TEST(GltfChecks, DirectoryIsRefused) {
    EXPECT_NE(refusalOf(dataPath("malformed")).find("is a directory"), std::string::npos);
}

}  // namespace
}  // namespace nimbus::assets
