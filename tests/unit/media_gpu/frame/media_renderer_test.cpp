// frame/media_settings.cpp's defaults, and common/medium_footprint.cpp: splatFootprint and automaticMediaScale,
// what media_scale=auto is chosen from, particlesNearMeshes, which particles balanced draws with the
// mesh-crossing variant, particlesNearLamps, which the splats draw with the fragment lamps, and the
// rects the fast tier draws its edges again within (billboardRect, nearMeshRect, lampImages and lampPeaks,
// intersectRects) and composes within (mediumRect, growRect),
// and particlesClearOfMeshes, which splats the depth test alone clips.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "nimbus/media/media_renderer.h"

namespace nimbus::media {
namespace {

// A 200×100 perspective view looking down −Z from the origin with tan(yfov/2) = 0.5: at depth d
// one metre spans 100/d pixels vertically.
gpu::View testView() {
    gpu::View view;
    view.width = 200;
    view.height = 100;
    view.tanHalfFovY = 0.5f;
    view.aspect = 2.0f;
    return view;
}

TEST(SplatFootprint, OneBillboardCoversItsSquare) {
    ParticleSet particles;
    particles.push({0.0, 0.0, -10.0}, 1.0f, 1.0f, Medium{});  // half size 10 px: a 20×20 quad
    const SplatFootprint f = splatFootprint(particles, testView());
    EXPECT_NEAR(f.coverage, 400.0 / 20000.0, 1e-12);
    EXPECT_NEAR(f.radiusPixels, 10.0, 1e-9);
}

TEST(SplatFootprint, TheRadiusIsWeightedByArea) {
    ParticleSet particles;
    particles.push({0.0, 0.0, -10.0}, 1.0f, 1.0f, Medium{});  // 10 px, area 400
    particles.push({0.0, 0.0, -10.0}, 0.1f, 1.0f, Medium{});  // 1 px, area 4
    const SplatFootprint f = splatFootprint(particles, testView());
    EXPECT_NEAR(f.radiusPixels, (10.0 * 400.0 + 1.0 * 4.0) / 404.0, 1e-6);  // radius 0.1f is not 0.1
}

TEST(SplatFootprint, AParticleAroundTheEyeCoversTheScreen) {
    ParticleSet particles;
    particles.push({0.0, 0.0, -0.5}, 1.0f, 1.0f, Medium{});
    EXPECT_DOUBLE_EQ(splatFootprint(particles, testView()).coverage, 1.0);
    EXPECT_DOUBLE_EQ(splatFootprint(ParticleSet{}, testView()).coverage, 0.0);
}

TEST(AutomaticMediaScale, FullResolutionUnlessFillDominates) {
    EXPECT_EQ(automaticMediaScale({.coverage = 2.0, .radiusPixels = 100.0}, 1.0, false), 1.0f);
    EXPECT_EQ(automaticMediaScale({.coverage = 10.0, .radiusPixels = 100.0}, 1.0, true), 1.0f) << "a lamp's light blurred";
}

// The upsampling costs the pixels it composes, not the image's: billboards covering a tenth of the
// image three times over pay for it.
TEST(AutomaticMediaScale, CoverageCountsOverThePixelsComposed) {
    EXPECT_EQ(automaticMediaScale({.coverage = 0.3, .radiusPixels = 100.0}, 0.2, false), 1.0f) << "1.5 times over its rect";
    EXPECT_EQ(automaticMediaScale({.coverage = 0.3, .radiusPixels = 100.0}, 0.1, false), 0.25f) << "3 times over its rect";
}

TEST(AutomaticMediaScale, KeepsEightTexelsAcrossATypicalBillboard) {
    EXPECT_EQ(automaticMediaScale({.coverage = 10.0, .radiusPixels = 16.0}, 1.0, false), 0.5f) << "never above ½";
    EXPECT_FLOAT_EQ(automaticMediaScale({.coverage = 10.0, .radiusPixels = 24.0}, 1.0, false), 1.0f / 3.0f);
    EXPECT_EQ(automaticMediaScale({.coverage = 10.0, .radiusPixels = 400.0}, 1.0, false), 0.25f) << "never below ¼";
}

TEST(AutomaticMediaScale, BillboardsThatHalfWouldBlurStayAtFullResolution) {
    // Half size 15.9 px keeps 7.95 texels at ½, under the 8 a reduced target must keep.
    EXPECT_EQ(automaticMediaScale({.coverage = 10.0, .radiusPixels = 15.9}, 1.0, false), 1.0f);
    EXPECT_EQ(automaticMediaScale({.coverage = 10.0, .radiusPixels = 2.0}, 1.0, false), 1.0f) << "a small image of a dense cloud";
}

TEST(AutomaticImpostorScale, KeepsSixTexelsAcrossATypicalBillboardInEighths) {
    EXPECT_EQ(automaticImpostorScale(24.0), 0.25f) << "6 texels of 24 at exactly a quarter";
    EXPECT_EQ(automaticImpostorScale(100.0), 0.25f) << "never below a quarter";
    EXPECT_EQ(automaticImpostorScale(20.0), 0.375f) << "0.3 rounded up to eighths: never fewer than 6 texels";
    EXPECT_EQ(automaticImpostorScale(12.0), 0.5f);
    EXPECT_EQ(automaticImpostorScale(3.0), 0.5f) << "never above a half";
    EXPECT_EQ(automaticImpostorScale(0.0), 0.5f) << "nothing drawn: the default";
}

TEST(ParticlesNearMeshes, ATiltedThinBoxReachesOnlyTheSpheresWithinReach) {
    ParticleSet particles;
    particles.push({0.0, 1.0, 0.0}, 0.5f, 1.0f, Medium{});  // 1 m above the box's plane
    // A 4 × 0.02 × 4 m plate through the origin, rolled 45° about z: its axis-aligned hull reaches y = 1.4.
    const double c = std::sqrt(0.5);
    OccluderBox plate;
    plate.axis[0] = {c, c, 0.0};
    plate.axis[1] = {-c, c, 0.0};
    plate.half = {2.0, 0.01, 2.0};
    EXPECT_EQ(particlesNearMeshes({plate}, particles, 1.0), std::vector<std::uint8_t>{0}) << "the sphere lies 0.7 m off the plate";
    EXPECT_EQ(particlesNearMeshes({plate}, particles, 1.5), std::vector<std::uint8_t>{1}) << "within 1.5 radii";
    particles.push({0.5, 0.5, 1.0}, 0.2f, 1.0f, Medium{});  // on the plate's plane
    EXPECT_EQ(particlesNearMeshes({plate}, particles, 1.0), (std::vector<std::uint8_t>{0, 1}));
    EXPECT_EQ(particlesNearMeshes({}, particles, 1.0), (std::vector<std::uint8_t>{0, 0}));
}

// A mesh box's axis-aligned hull decides: a box beside the medium's does not reach into it, one
// whose hull meets it does, even a tilted plate that itself passes the medium by (a cheap test that
// may err towards finer slices, never towards missing a mesh).
TEST(MeshReachesInto, TheMeshBoxsHullMeetsTheMediumsBounds) {
    const Aabb medium{glm::dvec3(-1.0), glm::dvec3(1.0)};
    OccluderBox beside;
    beside.centre = {3.0, 0.0, 0.0};
    beside.half = {1.5, 0.5, 0.5};
    EXPECT_FALSE(meshReachesInto({beside}, medium)) << "its near face lies 0.5 m off the box";
    beside.half.x = 2.0;
    EXPECT_TRUE(meshReachesInto({beside}, medium)) << "its near face touches the box";
    const double c = std::sqrt(0.5);
    OccluderBox plate;  // 4 × 0.02 × 4 m rolled 45° about z, centred 2.2 m up: its hull reaches y = 0.79, it y = 1.2 at x = −1
    plate.centre = {0.0, 2.2, 0.0};
    plate.axis[0] = {c, c, 0.0};
    plate.axis[1] = {-c, c, 0.0};
    plate.half = {2.0, 0.01, 2.0};
    EXPECT_TRUE(meshReachesInto({beside, plate}, medium));
    EXPECT_FALSE(meshReachesInto({}, medium));
    EXPECT_FALSE(meshReachesInto({plate}, Aabb{})) << "no medium";
}

// A ground or wall spans the medium across its two longest axes; a wing inside it does not.
TEST(BoxSpansMedium, AGroundSpansItAndAWingInsideItDoesNot) {
    const Aabb medium{glm::dvec3(-5.0, 2.0, -5.0), glm::dvec3(5.0, 8.0, 5.0)};
    OccluderBox ground;
    ground.half = {40.0, 0.0, 40.0};
    EXPECT_TRUE(boxSpansMedium(ground, medium));
    ground.half.z = 4.0;
    EXPECT_FALSE(boxSpansMedium(ground, medium)) << "a strip narrower than the medium";
    OccluderBox wall;  // upright, across x and y
    wall.centre = {0.0, 5.0, 1.0};
    wall.half = {6.0, 4.0, 0.1};
    EXPECT_TRUE(boxSpansMedium(wall, medium));
    OccluderBox wing;
    wing.centre = {0.0, 4.0, 0.0};
    wing.half = {4.5, 0.04, 1.1};
    EXPECT_FALSE(boxSpansMedium(wing, medium));
}

// A unit cube whose nearest face lies `gap` metres right of `p` (along +x).
OccluderBox cubeRightOf(const glm::dvec3& p, double gap) {
    OccluderBox box;
    box.centre = p + glm::dvec3(gap + 0.5, 0.0, 0.0);
    box.half = glm::dvec3(0.5);
    return box;
}

TEST(ParticlesClearOfMeshes, AMeshWithinTheQuadsReachNotOnlyTheSpheres) {
    // 2 m ahead with R = 1: the quad through the centre spans R·d/√(d² − R²) = 1.155 m of it.
    ParticleSet particles;
    particles.push({0.0, 0.0, -2.0}, 1.0f, 1.0f, Medium{});
    const gpu::View view = testView();
    EXPECT_EQ(particlesClearOfMeshes({}, particles, view), std::vector<std::uint8_t>{1}) << "no mesh at all";
    EXPECT_EQ(particlesClearOfMeshes({cubeRightOf({0.0, 0.0, -2.0}, 1.3)}, particles, view), std::vector<std::uint8_t>{1});
    EXPECT_EQ(particlesClearOfMeshes({cubeRightOf({0.0, 0.0, -2.0}, 1.1)}, particles, view), std::vector<std::uint8_t>{0})
        << "outside the sphere, but a ray through it meets the quad's plane beyond the mesh";
    gpu::View ortho = view;
    ortho.orthographic = true;
    EXPECT_EQ(particlesClearOfMeshes({cubeRightOf({0.0, 0.0, -2.0}, 1.1)}, particles, ortho), std::vector<std::uint8_t>{1})
        << "an orthographic quad reaches R";
}

TEST(ParticlesClearOfMeshes, NotWhereTheQuadCoversTheScreen) {
    ParticleSet particles;
    particles.push({0.0, 0.0, -0.5}, 1.0f, 1.0f, Medium{});   // around the eye
    particles.push({0.0, 0.0, -1.05}, 1.0f, 1.0f, Medium{});  // its front within twice the near plane
    particles.push({0.0, 0.0, -3.0}, 1.0f, 1.0f, Medium{});
    EXPECT_EQ(particlesClearOfMeshes({}, particles, testView()), (std::vector<std::uint8_t>{0, 0, 1}));
}

TEST(BillboardRect, BoundsTheFlaggedSpheresOnScreen) {
    ParticleSet particles;
    particles.push({0.0, 0.0, -10.0}, 1.0f, 1.0f, Medium{});  // its sphere spans 10.05 px each way from the centre (100, 50)
    particles.push({5.0, 0.0, -10.0}, 1.0f, 1.0f, Medium{});  // 50 px to the right, not flagged
    const glm::ivec4 rect = billboardRect(particles, {1, 0}, testView(), 0);
    EXPECT_LE(rect.x, 89);
    EXPECT_GE(rect.x, 87);
    EXPECT_LE(rect.y, 39);
    EXPECT_GE(rect.y, 37);
    EXPECT_GE(rect.x + rect.z, 111);
    EXPECT_LE(rect.x + rect.z, 113);
    EXPECT_GE(rect.y + rect.w, 61);
    EXPECT_LE(rect.y + rect.w, 63);
    EXPECT_EQ(billboardRect(particles, {1, 0}, testView(), 4), rect + glm::ivec4(-4, -4, 8, 8)) << "grown by the margin";
    EXPECT_EQ(billboardRect(particles, {0, 0}, testView(), 4).z, 0) << "none flagged";
}

TEST(BillboardRect, ASphereAroundTheEyeTakesTheView) {
    ParticleSet particles;
    particles.push({0.0, 0.0, -0.5}, 1.0f, 1.0f, Medium{});
    EXPECT_EQ(billboardRect(particles, {1}, testView(), 2), glm::ivec4(0, 0, 200, 100));
}

TEST(NearMeshRect, OnlyTheBoxesWithinReachOfAParticle) {
    const gpu::View view = gpu::makePerspectiveView({}, 2.0 * std::atan(0.5), 0.1, 0.0, 200, 100);
    ParticleSet particles;
    particles.push({0.0, 0.0, -10.0}, 1.0f, 1.0f, Medium{});
    OccluderBox inside, far;
    inside.centre = {0.5, 0.0, -10.0};
    inside.half = {1.0, 0.1, 0.1};  // from x −0.5 to 1.5 at depth 10: pixels 95..115, the sphere's 88..112
    far.centre = {-8.0, 0.0, -10.0};
    far.half = {0.5, 0.5, 0.5};
    const glm::ivec4 rect = nearMeshRect({inside, far}, particles, 2.0, view, 0);
    EXPECT_NEAR(rect.x, 94, 1);
    EXPECT_NEAR(rect.x + rect.z, 112, 1) << "where the box and its near particles meet";
    EXPECT_EQ(nearMeshRect({far}, particles, 2.0, view, 0).z, 0) << "8 radii away";
}

TEST(MediumRect, TheParticlesSpheresAndTheVolumesBoxes) {
    const gpu::View view = gpu::makePerspectiveView({}, 2.0 * std::atan(0.5), 0.1, 0.0, 200, 100);
    ParticleSet particles;
    particles.push({0.0, 0.0, -10.0}, 1.0f, 1.0f, Medium{});
    EXPECT_EQ(mediumRect(particles, {}, view, 3), billboardRect(particles, {1}, view, 3));
    // A 1 m box 5 m to the right at depth 10: its near face (depth 9.5) spans pixels 147..158.
    const Volume box = makeVolume(VolumeShape::Box, glm::translate(glm::dmat4(1.0), glm::dvec3(5.0, 0.0, -10.0)), glm::dvec3(1.0), Medium{});
    const glm::ivec4 both = mediumRect(particles, {box}, view, 0);
    EXPECT_NEAR(both.x + both.z, 158, 1) << "the volume's box widens it";
    EXPECT_NEAR(both.x, billboardRect(particles, {1}, view, 0).x, 0);
    EXPECT_EQ(mediumRect(ParticleSet{}, {}, view, 3).z, 0) << "nothing drawn";
}

// What the renderer draws again at full resolution for these lights (lampImages, then lampPeaks).
glm::ivec4 lampPeakRect(const ParticleSet& particles, const std::vector<Light>& lights, const gpu::View& view, int margin) {
    return lampPeaks(lampImages(particles, lights, view), view, margin).rect;
}

// A point light within two radii of a particle: the pixels within the margin of its image, where a
// reduced target's upsampling cannot follow its peak. None for a light far from every particle, a
// spot (whose cone edge is no point), or a point light behind the eye.
TEST(LampPeakRect, AroundAPointLightsImageAmongTheParticles) {
    const gpu::View view = gpu::makePerspectiveView({}, 2.0 * std::atan(0.5), 0.1, 0.0, 200, 100);
    ParticleSet particles;
    particles.push({0.0, 0.0, -10.0}, 1.0f, 1.0f, Medium{});
    Light lamp;
    lamp.kind = gpu::LightKind::Point;
    lamp.position = {1.0, 0.5, -10.0};  // 1.1 radii from the centre; its image at pixel (110, 55)
    const glm::ivec4 rect = lampPeakRect(particles, {lamp}, view, 5);
    EXPECT_NEAR(rect.x, 105, 1);
    EXPECT_NEAR(rect.y, 50, 1);
    EXPECT_NEAR(rect.z, 10, 1);
    EXPECT_NEAR(rect.w, 10, 1);
    Light far = lamp, spot = lamp, behind = lamp;
    far.position = {3.0, 0.0, -10.0};
    spot.kind = gpu::LightKind::Spot;
    behind.position = {0.0, 0.0, 1.0};
    ParticleSet aroundEye;
    aroundEye.push({0.0, 0.0, 0.0}, 2.0f, 1.0f, Medium{});
    EXPECT_EQ(lampPeakRect(particles, {far}, view, 5).z, 0) << "three radii away";
    EXPECT_EQ(lampPeakRect(particles, {spot}, view, 5).z, 0);
    EXPECT_EQ(lampPeakRect(aroundEye, {behind}, view, 5).z, 0) << "behind the eye";
    EXPECT_EQ(lampPeakRect(particles, {far, lamp}, view, 5), rect);
}

// The peaks are drawn again through one rect: lamps far apart on screen would redraw everything
// between them, so such a frame is not reduced for them.
TEST(LampPeakRect, LampsFarApartOnScreenAreNotCompact) {
    const gpu::View view = gpu::makePerspectiveView({}, 2.0 * std::atan(0.5), 0.1, 0.0, 200, 100);
    ParticleSet particles;
    particles.push({-6.0, 0.0, -10.0}, 1.0f, 1.0f, Medium{});
    particles.push({6.0, 0.0, -10.0}, 1.0f, 1.0f, Medium{});
    particles.push({-5.0, 0.0, -10.0}, 1.0f, 1.0f, Medium{});
    Light left, right, beside;
    left.kind = right.kind = beside.kind = gpu::LightKind::Point;
    left.position = {-6.0, 0.0, -10.0};   // pixel 40
    right.position = {6.0, 0.0, -10.0};   // pixel 160
    beside.position = {-5.5, 0.0, -10.0};  // pixel 45
    EXPECT_TRUE(lampPeaksCompact(lampImages(particles, {left}, view), view));
    EXPECT_TRUE(lampPeaksCompact(lampImages(particles, {left, beside}, view), view)) << "two squares that overlap";
    EXPECT_FALSE(lampPeaksCompact(lampImages(particles, {left, right}, view), view)) << "120 pixels apart";
    EXPECT_TRUE(lampPeaksCompact(lampImages(particles, {}, view), view));
    const LampPeaks both = lampPeaks(lampImages(particles, {left, right}, view), view, 5);
    EXPECT_EQ(both.pixels, 2LL * 10 * 10);
}

TEST(IntersectRects, TheSharedPixelsOrNone) {
    EXPECT_EQ(intersectRects({0, 0, 10, 10}, {5, 2, 10, 4}), glm::ivec4(5, 2, 5, 4));
    EXPECT_EQ(intersectRects({0, 0, 10, 10}, {10, 0, 5, 5}).z, 0);
    EXPECT_EQ(intersectRects({0, 0, 10, 10}, glm::ivec4(0)).z, 0);
}

TEST(ParticlesNearLamps, AParticleWithinReachOfAPointLight) {
    ParticleSet particles;
    particles.push({0.0, 0.0, 0.0}, 1.0f, 1.0f, Medium{});   // the lamp 1.5 radii away
    particles.push({5.0, 0.0, 0.0}, 1.0f, 1.0f, Medium{});   // 3.5 radii away
    particles.push({0.0, 0.0, 10.0}, 6.0f, 1.0f, Medium{});  // large: the lamp 1.8 of its radii away
    Light point;
    point.kind = gpu::LightKind::Point;
    point.position = {1.5, 0.0, 0.0};
    Light sun;
    const std::vector<Light> lights{sun, point};
    const int lamps[] = {1, -1};
    EXPECT_EQ(particlesNearLamps(particles, lights, lamps, 2.0), (std::vector<std::uint8_t>{1, 0, 1}));
    EXPECT_EQ(particlesNearLamps(particles, lights, lamps, 4.0), (std::vector<std::uint8_t>{1, 1, 1}));
    const int none[] = {-1, 1};  // −1 ends the list
    EXPECT_EQ(particlesNearLamps(particles, lights, none, 2.0), (std::vector<std::uint8_t>{0, 0, 0}));
}

TEST(ParticlesNearLamps, ASpotsConeEdgeCrossingASphereFarAway) {
    Light spot;
    spot.kind = gpu::LightKind::Spot;
    spot.direction = {0.0, 0.0, -1.0};
    spot.innerConeAngle = 0.2;
    spot.outerConeAngle = 0.3;
    ParticleSet particles;
    particles.push({0.0, 0.0, -20.0}, 1.0f, 1.0f, Medium{});                               // on the axis: inside the inner cone
    particles.push({20.0 * std::tan(0.25), 0.0, -20.0}, 1.0f, 1.0f, Medium{});             // between the two angles
    particles.push({20.0 * std::tan(0.32), 0.0, -20.0}, 1.0f, 1.0f, Medium{});             // just outside, its sphere across the edge
    particles.push({20.0 * std::tan(0.8), 0.0, -20.0}, 1.0f, 1.0f, Medium{});              // far outside
    const int lamps[] = {0, -1};
    EXPECT_EQ(particlesNearLamps(particles, {spot}, lamps, 2.0), (std::vector<std::uint8_t>{0, 1, 1, 0}));
}

TEST(MediaRenderSettings, ZeroFieldsTakeTheirDefaultsAndChosenOnesStay) {
    const MediaRenderSettings d = withDefaults({});
    EXPECT_EQ(d.sliceResolution, 256);
    EXPECT_EQ(d.mediaScale, 1.0f);
    EXPECT_EQ(d.upsampleThreshold, 0.2f);
    EXPECT_EQ(d.slices, 0) << "zero slices means: chosen from the medium";
    EXPECT_TRUE(d.mode.empty()) << "an empty mode is the technique table's first";
    const MediaRenderSettings set = withDefaults({.sliceResolution = 64, .mediaScale = 0.5f});
    EXPECT_EQ(set.sliceResolution, 64);
    EXPECT_EQ(set.mediaScale, 0.5f);
    EXPECT_EQ(withDefaults(set).mediaScale, 0.5f) << "applying it twice changes nothing";
}

}  // namespace
}  // namespace nimbus::media
