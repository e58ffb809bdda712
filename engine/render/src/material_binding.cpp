#include "material_binding.h"

namespace nimbus::render {
namespace {

void setTextureRef(GLuint program, GLint rowsLocation, GLint texCoordLocation, const assets::TextureRef& ref) {
    const glm::vec3 rows[2] = {ref.row0, ref.row1};
    glProgramUniform3fv(program, rowsLocation, 2, &rows[0][0]);
    glProgramUniform1i(program, texCoordLocation, ref.texCoord);
}

void bindTexture(GLuint unit, const gpu::Texture& texture, const gpu::Sampler& sampler) {
    glBindTextureUnit(unit, texture.id());
    glBindSampler(unit, sampler.id());
}

}  // namespace

unsigned materialFeatures(const GpuMaterial& material, const GpuPrimitive& primitive) {
    const assets::Material& m = material.params;
    unsigned f = 0;
    if (m.baseColorTexture.present()) f |= kBaseColorTexture;
    if (m.metallicRoughnessTexture.present()) f |= kMetallicRoughnessTexture;
    if (m.emissiveTexture.present()) f |= kEmissiveTexture;
    if (material.masked()) f |= kAlphaMask;
    if (primitive.vertexColors) f |= kVertexColor;
    return f;
}

unsigned shadowFeatures(unsigned features) {
    if (!(features & kAlphaMask)) return 0;
    return features & (kAlphaMask | kBaseColorTexture | kVertexColor);
}

std::vector<std::string> featureDefines(unsigned features) {
    std::vector<std::string> defines;
    if (features & kBaseColorTexture) defines.emplace_back("BASE_COLOR_TEXTURE");
    if (features & kMetallicRoughnessTexture) defines.emplace_back("METALLIC_ROUGHNESS_TEXTURE");
    if (features & kEmissiveTexture) defines.emplace_back("EMISSIVE_TEXTURE");
    if (features & kAlphaMask) defines.emplace_back("ALPHA_MASK");
    if (features & kVertexColor) defines.emplace_back("VERTEX_COLOR");
    return defines;
}

void bindMaterial(GLuint program, const GpuScene& scene, const GpuMaterial& material, unsigned features, bool shading) {
    const assets::Material& m = material.params;
    if (shading || (features & kAlphaMask)) {
        glProgramUniform4fv(program, 2, 1, &m.baseColorFactor[0]);
        glProgramUniform4f(program, 3, m.metallicFactor, m.roughnessFactor, m.alphaCutoff, 0.0f);
    }
    if (shading) glProgramUniform3fv(program, 4, 1, &m.emissiveFactor[0]);
    if (features & kBaseColorTexture) {
        setTextureRef(program, 5, 11, m.baseColorTexture);
        const GpuTexture& t = scene.texture(m.baseColorTexture.texture);
        bindTexture(kBaseColorUnit, t.srgb, t.sampler);
    }
    if (!shading) return;
    if (features & kMetallicRoughnessTexture) {
        setTextureRef(program, 7, 12, m.metallicRoughnessTexture);
        const GpuTexture& t = scene.texture(m.metallicRoughnessTexture.texture);
        bindTexture(kMetallicRoughnessUnit, t.linear, t.sampler);
    }
    if (features & kEmissiveTexture) {
        setTextureRef(program, 9, 13, m.emissiveTexture);
        const GpuTexture& t = scene.texture(m.emissiveTexture.texture);
        bindTexture(kEmissiveUnit, t.srgb, t.sampler);
    }
}

}  // namespace nimbus::render
