// A box covers exactly the pixels its projection says. The 8 world-space corners are projected
// with the View's viewProjection, the convex hull of the projected points is rasterised at pixel
// centres here, and every pixel more than one pixel from the hull's edge must be box-coloured
// inside and background outside.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "nimbus/assets/scene.h"
#include "render_fixture.h"
#include "scene_geometry.h"

namespace nimbus::test {
namespace {

struct CoverageCounts {
    int inside = 0, outside = 0, edge = 0;
    int badInside = 0, badOutside = 0;
    std::string firstBad;
};

// `isBoxColour` decides for pixels inside the hull; outside ones must equal the background.
template <class IsBoxColour>
CoverageCounts checkCoverage(const AppFrame& frame, const ConvexHull& hull, const glm::vec3& background, IsBoxColour isBoxColour) {
    CoverageCounts c;
    for (int y = 0; y < frame.image.height; ++y)
        for (int x = 0; x < frame.image.width; ++x) {
            const double d = hull.signedDistance({x + 0.5, y + 0.5});
            const glm::vec3 p = frame.image.at(x, y);
            auto report = [&](const char* what) {
                if (c.firstBad.empty())
                    c.firstBad = std::string(what) + " pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") = (" +
                                 std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
            };
            if (std::abs(d) <= 1.0) {
                ++c.edge;
            } else if (d < 0.0) {
                ++c.inside;
                if (!isBoxColour(p)) ++c.badInside, report("inside");
            } else {
                ++c.outside;
                if (glm::length(p - background) > 1e-6f) ++c.badOutside, report("outside");
            }
        }
    return c;
}

ConvexHull projectedHull(const AppFrame& frame, const assets::Scene& scene) {
    std::vector<glm::dvec2> points;
    for (const render::MeshInstance& instance : frame.instances) {
        for (const assets::Primitive& p : scene.meshes.at(static_cast<std::size_t>(instance.mesh)).primitives)
            for (const glm::dvec3& corner : corners(glm::dvec3(p.boundsMin), glm::dvec3(p.boundsMax), instance.world))
                points.push_back(projectToImage(frame.view, corner));
    }
    return ConvexHull(points);
}

class BoxCoverage : public GlSceneTest {};

TEST_F(BoxCoverage, KhronosBoxCoversItsProjection) {
    auto scene = std::make_shared<const assets::Scene>(assets::loadScene(NIMBUS_TEST_DATA_DIR "/khronos/Box/Box.gltf"));
    const AppFrame frame = renderThroughApp(scene, 160, 120);
    EXPECT_EQ(context().takeGlErrors().count, 0u);
    ASSERT_EQ(frame.instances.size(), 1u);
    EXPECT_TRUE(frame.camera.synthesized) << "Box has no camera: the framing camera is used";
    const ConvexHull hull = projectedHull(frame, *scene);
    ASSERT_GE(hull.vertices().size(), 4u);
    // Box's material is baseColor (0.8, 0, 0) and glTF's default metallic 1: a red metal under the
    // default sun and ambient. Only Schlick's grazing term reflects a little green and blue.
    const CoverageCounts c = checkCoverage(frame, hull, scene->environment.background, [](const glm::vec3& p) {
        return p.x > 0.05f && p.y <= 0.05f * p.x && p.z <= 0.05f * p.x;
    });
    EXPECT_EQ(c.badInside, 0) << c.firstBad;
    EXPECT_EQ(c.badOutside, 0) << c.firstBad;
    EXPECT_GT(c.inside, 160 * 120 / 5) << "the framing camera fills a good part of the image";
    EXPECT_GT(c.outside, 160 * 120 / 5);
    EXPECT_LT(c.edge, c.inside / 2);
}

// A scene built in memory: a scaled, rotated box 1e5 m from the world origin seen by the scene's
// own camera, lit by a sun plus ambient (so every face is brighter than the background).
struct FarScene {
    std::shared_ptr<assets::Scene> scene = std::make_shared<assets::Scene>();
    glm::vec3 base{0.2f, 0.9f, 0.3f};

    FarScene() {
        assets::Material m;
        m.baseColorFactor = glm::vec4(base, 1.0f);
        scene->materials.push_back(m);
        scene->meshes.push_back({"box", {box({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, 0)}});
        const glm::dvec3 centre(1.0e5, 20.0, -3.0e4);
        assets::Node boxNode;
        boxNode.name = "box";
        boxNode.mesh = 0;
        boxNode.translation = centre;
        boxNode.rotation = glm::angleAxis(0.6, glm::normalize(glm::dvec3(0.3, 1.0, 0.2)));
        boxNode.scale = {1.0, 2.0, 0.5};
        assets::Camera camera;
        camera.name = "cam";
        camera.yfov = 0.7;
        camera.znear = 0.1;
        scene->cameras.push_back(camera);
        assets::Node cameraNode;
        cameraNode.name = "cam";
        cameraNode.camera = 0;
        const glm::dvec3 eye = centre + glm::dvec3(2.5, 1.5, 4.0);
        const glm::dmat4 cameraWorld = glm::inverse(glm::lookAt(eye, centre, glm::dvec3(0, 1, 0)));
        cameraNode.translation = eye;
        cameraNode.rotation = glm::quat_cast(glm::dmat3(cameraWorld));
        assets::Light sun;
        sun.name = "sun";
        sun.intensity = 2.0f;
        scene->lights.push_back(sun);
        assets::Node sunNode;
        sunNode.name = "sun";
        sunNode.light = 0;
        sunNode.rotation = glm::angleAxis(-1.1, glm::normalize(glm::dvec3(1.0, 0.3, -0.2)));
        scene->nodes = {boxNode, cameraNode, sunNode};
        scene->rootNodes = {0, 1, 2};
        scene->environment.background = {0.01f, 0.02f, 0.04f};
        scene->environment.ambient = {0.05f, 0.05f, 0.05f};
    }

    // Radiance of a box pixel is base × (white light): its channels keep base's proportions.
    bool isBoxColour(const glm::vec3& p) const {
        const float ambientOnly = base.y * 0.05f;
        return p.y >= ambientOnly * 0.999f && std::abs(p.x / p.y - base.x / base.y) < 1e-3f &&
               std::abs(p.z / p.y - base.z / base.y) < 1e-3f;
    }
};

TEST_F(BoxCoverage, FarFromTheOriginWithTheScenesCamera) {
    FarScene far;
    const AppFrame frame = renderThroughApp(far.scene, 200, 150);
    EXPECT_EQ(context().takeGlErrors().count, 0u);
    EXPECT_EQ(frame.camera.name, "cam");
    ASSERT_EQ(frame.instances.size(), 1u);
    const ConvexHull hull = projectedHull(frame, *far.scene);
    const CoverageCounts c = checkCoverage(frame, hull, far.scene->environment.background,
                                           [&](const glm::vec3& p) { return far.isBoxColour(p); });
    EXPECT_EQ(c.badInside, 0) << c.firstBad;
    EXPECT_EQ(c.badOutside, 0) << c.firstBad;
    EXPECT_GT(c.inside, 1000);
    EXPECT_GT(c.outside, 1000);
}

// Nodes outside the scene that is shown (orphans when the file names its scenes) are not drawn
// (assets/scene_queries.h: nodesInScene). Here an orphan ground plane lies under the box.
// Disabled: spawnScene gives every node its MeshRenderer and render::gatherFrameInput draws every
// MeshRenderer, so the orphan is drawn today (lights and framing already skip it). Enable with the fix.
TEST_F(BoxCoverage, NodesOutsideTheShownSceneAreNotDrawn) {
    FarScene far;
    far.scene->meshes.push_back({"ground", {quad({-50, 0, -50}, {0, 0, 100}, {100, 0, 0}, 0)}});
    assets::Node ground;
    ground.name = "orphan_ground";
    ground.mesh = 1;
    ground.translation = far.scene->nodes[0].translation - glm::dvec3(0.0, 1.5, 0.0);
    far.scene->nodes.push_back(ground);  // in no scene: rootNodes stays {0, 1, 2}
    const AppFrame frame = renderThroughApp(far.scene, 200, 150);
    std::vector<glm::dvec2> points;
    const auto& p = far.scene->meshes[0].primitives[0];
    for (const glm::dvec3& corner : corners(glm::dvec3(p.boundsMin), glm::dvec3(p.boundsMax), assets::computeWorldTransforms(*far.scene, 0.0)[0]))
        points.push_back(projectToImage(frame.view, corner));
    const CoverageCounts c = checkCoverage(frame, ConvexHull(points), far.scene->environment.background,
                                           [&](const glm::vec3& q) { return far.isBoxColour(q); });
    EXPECT_EQ(c.badOutside, 0) << "the orphan ground was drawn: " << c.firstBad;
}

}  // namespace
}  // namespace nimbus::test
