// Every build of the media shaders that has variants compiles and links: the passes compile a
// variant only when a frame first needs it, so a broken combination (block_composite's 16, the
// splats' 8) would otherwise surface in a user's frame. The descriptions are the passes' own.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gpu/gl_test_context.h"
#include "blocks/block_composite_pass.h"
#include "blocks/block_impostor_lighting_pass.h"
#include "particles/particle_lighting_pass.h"
#include "particles/particle_pass.h"
#include "particles/particle_splat_pass.h"
#include "sheets/sheet_pass.h"
#include "nimbus/base/error.h"

namespace nimbus::media {
namespace {

class ShaderVariants : public gpu::test::GlTest {};

std::string describe(const gpu::ProgramDesc& desc) {
    std::string text = desc.compute.empty() ? desc.vertex + "+" + desc.fragment : desc.compute;
    for (const std::string& d : desc.defines) text += " " + d;
    return text;
}

void expectCompiles(const std::vector<gpu::ProgramDesc>& descs) {
    for (const gpu::ProgramDesc& desc : descs) {
        SCOPED_TRACE(describe(desc));
        try {
            const gpu::Program program = gpu::compileProgram(desc);
            EXPECT_NE(program.id(), 0u);
        } catch (const SystemError& e) {
            ADD_FAILURE() << e.what();
        }
    }
}

// A LocalLightPrograms build: without and with the lamps, in the single and the multiple model.
void addBothLightings(std::vector<gpu::ProgramDesc>& out, const gpu::ProgramDesc& desc) {
    for (bool multiple : {false, true}) {
        gpu::ProgramDesc model = desc;
        if (multiple) model.defines.push_back("MEDIA_MULTIPLE");
        out.push_back(model);
        out.push_back(LocalLightPrograms::withLocalLights(model));
    }
}

TEST_F(ShaderVariants, ExactParticles) {
    std::vector<gpu::ProgramDesc> descs;
    for (bool layerLight : {false, true}) addBothLightings(descs, particlesDesc(layerLight));
    expectCompiles(descs);
}

TEST_F(ShaderVariants, ParticleLighting) {
    std::vector<gpu::ProgramDesc> descs;
    for (bool exact : {false, true})
        for (bool constant : {false, true})
            for (bool crossings : {false, true})
                for (bool lampRuns : {false, true})
                    addBothLightings(descs, particleLightingDesc({.exact = exact, .constant = constant, .meshCrossings = crossings, .lampRuns = lampRuns}));
    expectCompiles(descs);
}

TEST_F(ShaderVariants, ParticleSplats) {
    std::vector<gpu::ProgramDesc> descs;
    for (bool eyeInside : {false, true})
        for (bool lamps : {false, true})
            for (bool constant : {false, true})
                for (bool crossings : {false, true})
                    for (bool multiple : {false, true})
                        for (bool pointLamps : {false, lamps})
                            for (bool farDepth : {false, true})
                                descs.push_back(particleSplatDesc({.eyeInside = eyeInside,
                                                                   .lamps = lamps,
                                                                   .pointLamps = pointLamps,
                                                                   .constant = constant,
                                                                   .meshCrossings = crossings,
                                                                   .multiple = multiple,
                                                                   .farDepth = farDepth}));
    expectCompiles(descs);
}

// The exact program as the splat pass draws the particles a mesh lies inside.
TEST_F(ShaderVariants, ParticleCutRuns) {
    std::vector<gpu::ProgramDesc> descs;
    for (bool rankList : {false, true}) addBothLightings(descs, particleCutRunDesc(rankList));
    expectCompiles(descs);
}

TEST_F(ShaderVariants, SheetSplats) {
    std::vector<gpu::ProgramDesc> descs{sheetCompositeDesc()};
    for (bool lamps : {false, true})
        for (bool constant : {false, true})
            for (bool multiple : {false, true})
                for (bool pointLamps : {false, lamps}) descs.push_back(sheetSplatDesc(lamps, constant, multiple, pointLamps));
    addBothLightings(descs, sheetExactDesc());
    expectCompiles(descs);
}

TEST_F(ShaderVariants, Raymarch) {
    expectCompiles({{.vertex = "fullscreen.vert", .fragment = "media/raymarch/raymarch.frag"},
                    {.vertex = "fullscreen.vert", .fragment = "media/raymarch/raymarch.frag", .defines = {"MEDIA_MULTIPLE"}}});
}

TEST_F(ShaderVariants, BlockComposite) {
    std::vector<gpu::ProgramDesc> descs;
    for (std::uint8_t build = 0; build < 8; ++build) addBothLightings(descs, blockCompositeDesc(build));
    // The light read from the impostor texels, cut or not (never with the exact shading), and the
    // pass that shades it.
    for (const std::uint8_t build : {0, 1, 2, 3}) addBothLightings(descs, blockCompositeDesc(build | kBlockLitImpostor));
    for (const bool own : {false, true}) addBothLightings(descs, blockImpostorLightingDesc(own));
    expectCompiles(descs);
}

}  // namespace
}  // namespace nimbus::media
