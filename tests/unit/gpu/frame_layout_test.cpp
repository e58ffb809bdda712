// frame_layout.h against its GLSL twins (shaders/common/frame.glsl, lights.glsl, light_views.glsl,
// shadow_views.glsl), as the driver lays them out in the opaque program, which binds every one of
// them, with their binding points.
#include "nimbus/gpu/frame_layout.h"

#include <cstddef>

#include "gl_test_context.h"
#include "glsl_layout.h"
#include "nimbus/gpu/light_views.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::gpu {
namespace {

using test::expectMembers;

class FrameLayout : public test::GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        program_ = compileProgram({.vertex = "opaque.vert", .fragment = "opaque.frag"});
    }
    GLuint program() const { return program_.id(); }
    Program program_;
};

TEST_F(FrameLayout, FrameMatchesGpuFrame) {
    expectMembers(program(), GL_UNIFORM, "Frame.",
                  {{"viewProjection", offsetof(GpuFrame, viewProjection)},
                   {"viewMatrix", offsetof(GpuFrame, view)},
                   {"inverseViewProjection", offsetof(GpuFrame, inverseViewProjection)},
                   {"cameraRight", offsetof(GpuFrame, cameraRight)},
                   {"cameraUp", offsetof(GpuFrame, cameraUp)},
                   {"cameraForward", offsetof(GpuFrame, cameraForward)},
                   {"depthParams", offsetof(GpuFrame, depthParams)},
                   {"viewport", offsetof(GpuFrame, viewport)},
                   {"ambient", offsetof(GpuFrame, ambient)},
                   {"background", offsetof(GpuFrame, background)},
                   {"counts", offsetof(GpuFrame, counts)},
                   {"fogColor", offsetof(GpuFrame, fogColor)},
                   {"fogParams", offsetof(GpuFrame, fogParams)},
                   {"fogHeight", offsetof(GpuFrame, fogHeight)}});
    EXPECT_EQ(test::blockSize(program(), GL_UNIFORM_BLOCK, "Frame"), static_cast<GLint>(sizeof(GpuFrame)));
}

// A struct in an array of a uniform block: its members at their offsets, and the stride (from
// element 0 to element 1) and the block's size equal to the C++ struct's and the capacity's.
void expectUniformArray(GLuint program, const std::string& block, const std::string& array, std::size_t stride,
                        std::size_t capacity, const std::vector<test::MemberOffset>& members) {
    expectMembers(program, GL_UNIFORM, array + "[0].", members);
    const std::string first = array + "[0]." + members.front().name, second = array + "[1]." + members.front().name;
    EXPECT_EQ(test::resourceOffset(program, GL_UNIFORM, second) - test::resourceOffset(program, GL_UNIFORM, first),
              static_cast<GLint>(stride))
        << array;
    EXPECT_EQ(test::blockSize(program, GL_UNIFORM_BLOCK, block), static_cast<GLint>(stride * capacity)) << block;
}

TEST_F(FrameLayout, LightsMatchGpuLight) {
    expectUniformArray(program(), "Lights", "lights", sizeof(GpuLight), kMaxLights,
                       {{"position", offsetof(GpuLight, position)},
                        {"direction", offsetof(GpuLight, direction)},
                        {"radiance", offsetof(GpuLight, radiance)},
                        {"spot", offsetof(GpuLight, spot)}});
}

TEST_F(FrameLayout, ShadowViewsMatchGpuLightView) {
    const std::vector<test::MemberOffset> members = {{"view", offsetof(GpuLightView, view)},
                                                          {"viewProjection", offsetof(GpuLightView, viewProjection)},
                                                          {"params", offsetof(GpuLightView, params)},
                                                          {"params2", offsetof(GpuLightView, params2)}};
    expectUniformArray(program(), "ShadowViews", "shadowViews", sizeof(GpuLightView), kMaxLightViews, members);
}

TEST_F(FrameLayout, BlocksSitAtTheirBindingPoints) {
    const auto binding = [&](const char* block) { return test::resourceProperty(program(), GL_UNIFORM_BLOCK, block, GL_BUFFER_BINDING); };
    EXPECT_EQ(binding("Frame"), static_cast<GLint>(kFrameUniformBinding));
    EXPECT_EQ(binding("Lights"), static_cast<GLint>(kLightsBinding));
    EXPECT_EQ(binding("ShadowViews"), static_cast<GLint>(kShadowViewsBinding));
}

// A point light's faces carry the share of the layer's side they are drawn in (shadow_views.glsl
// shadowLayerUv) and texels as large as that side makes them; other views the whole layer.
TEST(PackLights, PointFacesCarryTheShareOfTheLayerTheyAreDrawnIn) {
    PunctualLight sun, lamp;
    sun.kind = LightKind::Directional;
    sun.direction = glm::dvec3(0.0, -1.0, 0.0);
    lamp.kind = LightKind::Point;
    lamp.position = glm::dvec3(0.0, 1.0, 0.0);
    const Aabb bounds{glm::dvec3(-2.0), glm::dvec3(2.0)};
    const std::vector<std::vector<LightView>> views{makeLightViews(sun, bounds, glm::dvec3(0.0)), makeLightViews(lamp, bounds, glm::dvec3(0.0))};
    const PackedLights half = packLights({sun, lamp}, glm::dvec3(0.0), views, 1024, 512);
    ASSERT_EQ(half.shadowViews.size(), 7u);
    EXPECT_EQ(half.shadowViews[0].params.w, 1.0f);
    EXPECT_FLOAT_EQ(half.shadowViews[0].params2.y, 2.0f * views[0][0].halfExtent.x / 1024.0f);
    for (std::size_t f = 1; f < 7; ++f) {
        EXPECT_EQ(half.shadowViews[f].params.w, 0.5f) << f;
        EXPECT_FLOAT_EQ(half.shadowViews[f].params2.y, 2.0f * views[1][f - 1].halfExtent.x / 512.0f) << f;
        EXPECT_EQ(half.shadowViews[f].params2.x, static_cast<float>(f)) << "one layer a face";
    }
    const PackedLights whole = packLights({sun, lamp}, glm::dvec3(0.0), views, 1024);
    for (const GpuLightView& v : whole.shadowViews) EXPECT_EQ(v.params.w, 1.0f);
    // The side the shadow pass draws in: only a point light's faces, never past the layer.
    EXPECT_EQ(shadowViewSide(LightKind::Point, 1024, 512), 512);
    EXPECT_EQ(shadowViewSide(LightKind::Spot, 1024, 512), 1024);
    EXPECT_EQ(shadowViewSide(LightKind::Directional, 1024, 512), 1024);
    EXPECT_EQ(shadowViewSide(LightKind::Point, 1024, 0), 1024);
    EXPECT_EQ(shadowViewSide(LightKind::Point, 1024, 4096), 1024);
}

}  // namespace
}  // namespace nimbus::gpu
