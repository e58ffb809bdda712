// Opaque meshes, shaded with glTF's metallic-roughness BRDF, mesh shadows and what extensions add
// (the medium's transmittance; shaders/opaque.*), one program variant per material's features and
// the frame's lights.
// Writes the output (linear RGBA32F, cleared to the background radiance; compose blends the media
// over it) and reversed-Z depth, which later passes read for soft particles and mesh–medium
// intersections.
#include "passes.h"

#include "material_binding.h"

#include <algorithm>

#include <glm/gtc/matrix_inverse.hpp>

#include "nimbus/gpu/shader_program.h"

namespace nimbus::render {

OpaquePass::OpaquePass() = default;

const gpu::Program& OpaquePass::program(const Variant& variant) {
    auto it = programs_.find(variant);
    if (it == programs_.end()) {
        std::vector<std::string> defines = featureDefines(variant.features);
        defines.insert(defines.end(), variant.extensions.begin(), variant.extensions.end());
        defines.push_back("VERTEX_LIGHTS " + std::to_string(variant.vertexLights));
        defines.push_back("VERTEX_DIRECTIONAL_LIGHTS " + std::to_string(variant.directionalMask) + "u");
        if (variant.fragmentLights) defines.emplace_back("FRAGMENT_LIGHTS");
        if (variant.pointFragmentLights) defines.emplace_back("POINT_FRAGMENT_LIGHTS");
        defines.push_back("PCF_RADIUS " + std::to_string(variant.pcfRadius));
        it = programs_.emplace(variant, gpu::compileProgram({.vertex = "opaque.vert", .fragment = "opaque.frag", .defines = defines})).first;
    }
    return it->second;
}

// The frame's part of the variant: the extensions, the PCF kernel, and the lights. The first lights
// with at most one view each (not a point light's cube), up to opaque.vert's four, get their
// shadow-map and light-slice coordinates from the vertex stage. Where the rest are all point lights,
// the fragments know it: their lookups then read no view's matrices (common/light_views.glsl).
OpaquePass::Variant OpaquePass::frameVariant(const FrameContext& context) {
    constexpr int kMaxVertexLights = 4;
    const auto& lights = context.input.lights;
    Variant variant;
    for (const auto& input : context.meshShading) variant.extensions.push_back(input.define);
    variant.pcfRadius = context.settings.pcfRadius;
    while (variant.vertexLights < std::min(kMaxVertexLights, static_cast<int>(lights.size()))) {
        const assets::LightType type = lights[static_cast<std::size_t>(variant.vertexLights)].params.type;
        if (type == assets::LightType::Point) break;
        if (type == assets::LightType::Directional) variant.directionalMask |= 1u << variant.vertexLights;
        ++variant.vertexLights;
    }
    variant.fragmentLights = static_cast<int>(lights.size()) > variant.vertexLights;
    variant.pointFragmentLights = variant.fragmentLights && std::all_of(lights.begin() + variant.vertexLights, lights.end(), [](const auto& light) {
        return light.params.type == assets::LightType::Point;
    });
    return variant;
}

void OpaquePass::add(FrameGraph& graph, FrameContext& context, const ShadowPass& shadows, const gpu::Texture& output) {
    struct Data {
        ResourceHandle color, depth, shadowMap;
        std::vector<std::pair<GLuint, ResourceHandle>> textures;  // the extensions' (unit, texture)
    };
    const int w = context.view.width, h = context.view.height;
    const auto& data = graph.addPass<Data>(
        "opaque",
        [&](PassBuilder& builder, Data& d) {
            d.color = builder.write(graph.importTexture("output", output));
            d.depth = builder.create("scene_depth", {GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, w, h, 1, 1});
            if (context.shadowMap.valid()) d.shadowMap = builder.read(context.shadowMap);
            for (const auto& input : context.meshShading)
                for (const auto& [unit, texture] : input.textures) d.textures.emplace_back(unit, builder.read(texture));
        },
        [this, &context, &shadows, w, h](const PassResources& resources, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, resources.id(d.color), 0);
            glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, resources.id(d.depth), 0);
            glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, w, h);
            const glm::vec4 background(context.input.environment.background, 1.0f);
            glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, &background[0]);
            const float clearDepth = 0.0f;  // reversed Z: 0 is infinitely far
            glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &clearDepth);

            context.frameData->bind();
            for (const auto& input : context.meshShading)
                if (input.bind) input.bind();
            if (d.shadowMap.valid()) {
                glBindTextureUnit(kShadowMapUnit, resources.id(d.shadowMap));
                glBindSampler(kShadowMapUnit, shadows.compareSampler_.id());
            }
            for (const auto& [unit, texture] : d.textures) glBindTextureUnit(unit, resources.id(texture));
            gpu::applyPipeline({.depth = {.test = true, .compare = GL_GREATER, .write = true}});  // reversed Z
            Variant variant = frameVariant(context);
            auto pick = [this, &variant](const GpuMaterial& material, const GpuPrimitive& primitive) {
                variant.features = materialFeatures(material, primitive);
                return std::make_pair(program(variant).id(), variant.features);
            };
            drawInstances(context, {.normalMatrixLocation = 1, .cullSingleSided = true, .shading = true, .program = pick});
            glBindSampler(kShadowMapUnit, 0);
        });
    context.sceneColor = data.color;
    context.sceneDepth = data.depth;
}

void drawInstances(const FrameContext& context, const DrawOptions& options) {
    const GpuScene& scene = *context.input.gpuScene;
    GLuint current = 0;
    for (const auto& instance : context.input.instances) {
        glm::dmat4 relative = instance.world;
        relative[3] -= glm::dvec4(context.view.origin, 0.0);
        const glm::mat4 model(relative);
        const glm::mat3 normalMatrix(glm::inverseTranspose(glm::dmat3(instance.world)));
        // A mirroring transform flips triangle winding; front faces follow the determinant's sign.
        const bool mirrored = glm::determinant(glm::dmat3(instance.world)) < 0.0;
        glFrontFace(mirrored ? GL_CW : GL_CCW);
        for (const auto& primitive : scene.primitives(instance.mesh)) {
            const GpuMaterial& material = scene.material(primitive.material);
            const auto [program, features] = options.program(material, primitive);
            if (program != current) glUseProgram(current = program);
            glProgramUniformMatrix4fv(program, 0, 1, GL_FALSE, &model[0][0]);
            if (options.normalMatrixLocation >= 0)
                glProgramUniformMatrix3fv(program, options.normalMatrixLocation, 1, GL_FALSE, &normalMatrix[0][0]);
            if (options.cullSingleSided && !material.doubleSided()) {
                glEnable(GL_CULL_FACE);
                glCullFace(GL_BACK);
            } else {
                glDisable(GL_CULL_FACE);
            }
            bindMaterial(program, scene, material, features, options.shading);
            glBindVertexArray(primitive.vertexArray.id());
            glDrawElements(GL_TRIANGLES, primitive.indexCount, GL_UNSIGNED_INT, nullptr);
        }
    }
    glFrontFace(GL_CCW);
    glBindVertexArray(0);
    for (const GLuint unit : {kBaseColorUnit, kMetallicRoughnessUnit, kEmissiveUnit}) glBindSampler(unit, 0);
}

}  // namespace nimbus::render
