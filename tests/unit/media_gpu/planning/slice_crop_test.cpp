// Tests plugins/participating_media/core/src/planning/slice_crop.cpp: a directional light's crop
// over where a mesh box reaches into the medium: narrowed to the overlap but never more than
// kCropGain finer, inside the whole view with the same view depth, its first plane a margin before
// the mesh, and none where it would not pay.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "nimbus/media/slice_plan.h"
#include "planning/slice_crop.h"

namespace nimbus::media {
namespace {

const glm::dvec3 kOrigin(0.0);
const Aabb kMedium{glm::dvec3(-10.0, 0.0, -10.0), glm::dvec3(10.0, 8.0, 10.0)};

gpu::LightView sunView() {
    gpu::PunctualLight sun;
    sun.kind = gpu::LightKind::Directional;
    sun.direction = glm::normalize(glm::dvec3(0.02, -1.0, 0.01));  // near vertical: depth is height
    return gpu::makeLightViews(sun, kMedium, kOrigin).front();
}

OccluderBox boxAt(const glm::dvec3& lo, const glm::dvec3& hi) { return occluderBox(glm::dmat4(1.0), lo, hi); }

TEST(SliceCrop, NarrowsToTheMeshButNoMoreThanTheGain) {
    const gpu::LightView whole = sunView();
    // A small box near one corner of the medium, half way down.
    const auto crop = meshCropView(whole, 16, {boxAt(glm::dvec3(5.0, 3.0, 5.0), glm::dvec3(6.0, 4.0, 6.0))}, kMedium, 0.5, kOrigin);
    ASSERT_TRUE(crop.has_value());
    EXPECT_NEAR(crop->view.halfExtent.x, whole.halfExtent.x / kCropGain, 1e-4);
    EXPECT_NEAR(crop->view.halfExtent.y, whole.halfExtent.y / kCropGain, 1e-4);
    EXPECT_LT(crop->view.depthFar, whole.depthFar);
    // Its first plane lies the margin before the box's top (the sun is near vertical: depth is
    // height below the view's origin), so a particle reaching the box lies wholly past it.
    const double spacing = (crop->view.depthFar - crop->view.depthNear) / crop->slices;
    const float boxTop = gpu::lightViewDepth(whole, glm::vec3(5.0f, 4.0f, 5.0f));
    EXPECT_NEAR(crop->view.depthNear + spacing, boxTop - 0.5 - 0.5, 0.1);
    EXPECT_GT(crop->view.depthNear + spacing, whole.depthNear + 1.0);
    // The crop keeps the whole view's depth and holds the box; it lies inside the whole view.
    for (const glm::dvec3& p : {glm::dvec3(5.5, 3.5, 5.5), glm::dvec3(5.0, 3.0, 5.0)}) {
        const glm::vec4 h(glm::vec3(p - kOrigin), 1.0f);
        EXPECT_FLOAT_EQ(gpu::lightViewDepth(crop->view, glm::vec3(h)), gpu::lightViewDepth(whole, glm::vec3(h)));
        const glm::vec4 clip = crop->view.viewProjection * h;
        EXPECT_LE(std::abs(clip.x), 1.0f);
        EXPECT_LE(std::abs(clip.y), 1.0f);
        EXPECT_GE(clip.z, 0.0f);
    }
    for (const glm::dvec3& corner : {glm::dvec3(-1.0, -1.0, 0.0), glm::dvec3(1.0, 1.0, 0.0)}) {
        const glm::vec4 atCorner = glm::inverse(crop->view.viewProjection) * glm::vec4(glm::vec3(corner), 1.0f);
        const glm::vec4 inWhole = whole.viewProjection * atCorner;
        EXPECT_LE(std::abs(inWhole.x), 1.0f + 1e-5f);
        EXPECT_LE(std::abs(inWhole.y), 1.0f + 1e-5f);
    }
    // Its planes are kCropGain closer than the whole view's 16 over the whole depth.
    const double wholeSpacing = (whole.depthFar - whole.depthNear) / 16.0;
    EXPECT_LE(spacing, wholeSpacing / kCropGain + 1e-9);
    EXPECT_EQ(crop->slices % 4, 0);
}

TEST(SliceCrop, NoneWhereItWouldNotPay) {
    const gpu::LightView whole = sunView();
    // No mesh box meets the medium.
    EXPECT_FALSE(meshCropView(whole, 16, {boxAt(glm::dvec3(20.0), glm::dvec3(21.0))}, kMedium, 0.5, kOrigin).has_value());
    // A mesh around the whole medium: as wide as the whole view and as deep.
    EXPECT_FALSE(meshCropView(whole, 16, {boxAt(glm::dvec3(-50.0, -1.0, -50.0), glm::dvec3(50.0, 20.0, 50.0))}, kMedium, 0.5, kOrigin).has_value());
    // A point light's perspective views are never cropped.
    gpu::PunctualLight lamp;
    lamp.kind = gpu::LightKind::Point;
    lamp.position = glm::dvec3(0.0, 4.0, 0.0);
    const gpu::LightView face = gpu::makeLightViews(lamp, kMedium, kOrigin).front();
    EXPECT_FALSE(meshCropView(face, 16, {boxAt(glm::dvec3(-1.0), glm::dvec3(1.0))}, kMedium, 0.5, kOrigin).has_value());
}

TEST(SliceCrop, AWideMeshHighInTheMediumTakesAShallowCrop) {
    const gpu::LightView whole = sunView();
    // A plate across the whole medium near its top (the sun above): as wide, but the slices need
    // only reach a little below it.
    const auto crop = meshCropView(whole, 16, {boxAt(glm::dvec3(-50.0, 6.0, -50.0), glm::dvec3(50.0, 6.2, 50.0))}, kMedium, 0.5, kOrigin);
    ASSERT_TRUE(crop.has_value());
    EXPECT_GT(crop->view.halfExtent.x, 0.9 * whole.halfExtent.x);
    EXPECT_LT(crop->view.depthFar - crop->view.depthNear, 0.5 * (whole.depthFar - whole.depthNear));
}

TEST(SliceCrop, AGroundUnderTheMediumTakesAShallowCropAtItsBase) {
    const gpu::LightView whole = sunView();
    // The ground cuts the particles at the medium's base: its planes start just above it and are
    // seeded there from the whole view, so the particles above are not drawn again.
    const auto crop = meshCropView(whole, 16, {boxAt(glm::dvec3(-50.0, -1.0, -50.0), glm::dvec3(50.0, 0.5, 50.0))}, kMedium, 0.5, kOrigin);
    ASSERT_TRUE(crop.has_value());
    const double spacing = (crop->view.depthFar - crop->view.depthNear) / crop->slices;
    EXPECT_GT(crop->view.depthNear + spacing, whole.depthNear + 0.7 * (whole.depthFar - whole.depthNear));
    EXPECT_NEAR(crop->view.depthFar, whole.depthFar, 0.1);
}

}  // namespace
}  // namespace nimbus::media
