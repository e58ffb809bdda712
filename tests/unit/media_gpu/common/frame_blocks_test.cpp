#include "common/frame_blocks.h"

#include <gtest/gtest.h>

#include "nimbus/base/error.h"
#include "nimbus/gpu/light_views.h"

namespace nimbus::media {
namespace {

std::vector<gpu::LightView> lampFaces() {
    gpu::PunctualLight lamp;
    lamp.kind = gpu::LightKind::Point;
    lamp.position = {1.0, 2.0, 0.5};
    return gpu::makeLightViews(lamp, {glm::dvec3(-4.0), glm::dvec3(4.0)}, glm::dvec3(0.0));
}

TEST(CheckCubeFaces, TakesMakeLightViewsFaces) {
    HostShadowMaps shadows{.texture = 1, .size = 256, .views = {{}, lampFaces()}};
    ASSERT_EQ(shadows.views[1].size(), 6u);
    EXPECT_NO_THROW(checkCubeFaces(shadows));
}

TEST(CheckCubeFaces, RefusesFacesInAnotherOrderNamingTheLightAndView) {
    HostShadowMaps shadows{.texture = 1, .size = 256, .views = {{}, lampFaces()}};
    std::swap(shadows.views[1][2], shadows.views[1][3]);  // −Y before +Y
    try {
        checkCubeFaces(shadows);
        FAIL() << "faces out of order were taken";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("light 1"), std::string::npos) << message;
        EXPECT_NE(message.find("view 2"), std::string::npos) << message;
        EXPECT_NE(message.find("+Y"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace nimbus::media
