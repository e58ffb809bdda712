// Volumes (a node's `volume` object, docs/scene-format.md §3) in `raymarch` and in the reference, on
// the scenes of tests/data/volume_scenes (generate_volume_scenes.py): a constant box against its
// closed form per pixel, lit volumes and a volume beside particles against the reference, the
// particle modes' refusal, and the hard cases finite. Real-time bounds are 1.5 × what was measured
// when they were set.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "media_test_support.h"
#include "nimbus/base/error.h"
#include "nimbus/media/reference/camera_rays.h"

namespace nimbus::test::media {
namespace {

namespace ref = nimbus::media::reference;

std::filesystem::path volumeScene(const std::string& name) {
    return std::filesystem::path(NIMBUS_TEST_DATA_DIR) / "volume_scenes" / (name + ".gltf");
}

sandbox::SessionOptions raymarch(const std::string& scene, assets::Scattering model = assets::Scattering::Single) {
    return {.scene = volumeScene(scene), .settings = {"mode=raymarch"}, .scattering = model};
}

// absorber_box's closed form: background × e^(−σ L) for the chord L of each pixel's ray.
assets::RgbImage closedFormAbsorber(sandbox::Session& session, int width, int height) {
    const auto scene = sandbox::makeReferenceScene(session, "", width, height);
    const ref::CameraFrame frame = ref::makeCameraFrame(scene->inputs.camera, width, height);
    EXPECT_EQ(scene->volumes.size(), 1u);
    const nimbus::media::Volume& box = scene->volumes.at(0);
    assets::RgbImage out;
    out.width = width;
    out.height = height;
    out.rgb.resize(static_cast<std::size_t>(3 * width * height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const ref::CameraRay ray = ref::cameraRay(frame, x, y);
            const nimbus::media::VolumeChord chord = nimbus::media::volumeChord(box, ray.origin, ray.direction);
            const double length = chord.hit() ? std::max(0.0, chord.exit - std::max(chord.enter, 0.0)) : 0.0;
            const auto t = static_cast<float>(std::exp(-box.sigma() * length));
            for (int c = 0; c < 3; ++c) out.rgb[static_cast<std::size_t>(3 * (y * width + x) + c)] = t;  // background [1, 1, 1]
        }
    return out;
}

class VolumeScenes : public GlSceneTest {};

TEST_F(VolumeScenes, ReferenceIsTheClosedFormOfAConstantBox) {
    sandbox::Session session(raymarch("absorber_box"));
    const assets::RgbImage exact = closedFormAbsorber(session, 48, 27);
    const assets::RgbImage reference = renderReference(session, 48, 27);
    double worst = 0.0;
    for (std::size_t i = 0; i < exact.rgb.size(); ++i) worst = std::max(worst, static_cast<double>(std::abs(reference.rgb[i] - exact.rgb[i]) / std::max(exact.rgb[i], 1e-3f)));
    EXPECT_LE(worst, 1e-4);
}

TEST_F(VolumeScenes, RaymarchOfAConstantBoxIsNearItsClosedForm) {
    sandbox::Session session(raymarch("absorber_box"));
    const auto metrics = ref::compareImages(session.renderRealtime(160, 90), closedFormAbsorber(session, 160, 90));
    EXPECT_EQ(metrics.nonfinite, 0u);
    EXPECT_LE(metrics.relRmse, 0.0045);  // 0.29 %: the grid's one-voxel ramp at the faces
    std::printf("[ measured ] raymarch absorber_box rel_rmse=%.4f against e^(-sigma L)\n", metrics.relRmse);
}

struct VolumeCase {
    const char* scene;
    assets::Scattering model;
    double bound;
    double time = 0.0;
};

void PrintTo(const VolumeCase& c, std::ostream* os) { *os << c.scene; }

class VolumeVsReference : public GlSceneTest, public ::testing::WithParamInterface<VolumeCase> {};

TEST_P(VolumeVsReference, RaymarchWithinTheScenesBound) {
    const VolumeCase& c = GetParam();
    sandbox::SessionOptions options = raymarch(c.scene, c.model);
    options.time = c.time;
    sandbox::Session session(options);
    const auto scene = sandbox::makeReferenceScene(session, "", 96, 54);
    ref::ReferenceSettings settings{.width = 96, .height = 54, .spp = 64, .scattering = c.model, .progress = false};
    const assets::RgbImage reference = ref::renderReference(scene->inputs, settings);
    const auto metrics = ref::compareImages(session.renderRealtime(96, 54), reference);
    EXPECT_EQ(metrics.nonfinite, 0u);
    EXPECT_LE(metrics.relRmse, c.bound);
    std::printf("[ measured ] raymarch %s %s rel_rmse=%.4f (bound %.3f)\n", c.scene, c.model == assets::Scattering::Multiple ? "multiple" : "single",
                metrics.relRmse, c.bound);
}

INSTANTIATE_TEST_SUITE_P(Volumes, VolumeVsReference,
                         ::testing::Values(VolumeCase{"lit_ellipsoid", assets::Scattering::Single, 0.005},      // 0.32 %
                                           VolumeCase{"lit_ellipsoid", assets::Scattering::Multiple, 0.057},   // 3.8 % (the judge's noise 0.2 %)
                                           VolumeCase{"mixed", assets::Scattering::Single, 0.003},            // 0.20 %
                                           // Noise sampled at the grid's voxel centres on the GPU, the judge's to the bit there.
                                           VolumeCase{"noise_value", assets::Scattering::Single, 0.002},      // 0.042 %
                                           VolumeCase{"noise_value", assets::Scattering::Single, 0.002, 1.5}, // 0.046 %, drifted 0.9 m
                                           VolumeCase{"noise_sines", assets::Scattering::Single, 0.0093}),    // 0.62 %
                         [](const ::testing::TestParamInfo<VolumeCase>& param) {
                             return std::string(param.param.scene) + (param.param.model == assets::Scattering::Multiple ? "_multiple" : "_single") +
                                    (param.param.time > 0.0 ? "_later" : "");
                         });

// The noise drifts with its velocity: the same node at another time shows another pattern (and the
// judge agrees with it there: VolumeVsReference's noise_value_single_later).
TEST_F(VolumeScenes, NoiseDriftsWithItsVelocity) {
    auto frame = [](double time) {
        sandbox::SessionOptions options = raymarch("noise_value");
        options.time = time;
        sandbox::Session session(options);
        return session.renderRealtime(96, 54);
    };
    const assets::RgbImage start = frame(0.0), later = frame(1.5), again = frame(0.0);
    EXPECT_GT(ref::compareImages(later, start).relRmse, 0.02);
    EXPECT_EQ(ref::compareImages(again, start).relRmse, 0.0);
}

// A mode that does not draw volumes refuses the scene in one line naming the file, the node and the
// field, and the modes that do.
TEST_F(VolumeScenes, ParticleModesRefuseAVolumeNamingItsNode) {
    for (const char* mode : {"particles", "blocks", "sheets", "billboards"}) {
        SCOPED_TRACE(mode);
        sandbox::Session session({.scene = volumeScene("absorber_box"), .settings = {std::string("mode=") + mode}});
        try {
            (void)session.renderRealtime(32, 18);
            ADD_FAILURE() << "rendered a volume in " << mode;
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("absorber_box.gltf: node \"box\" (nodes[0])"), std::string::npos) << message;
            EXPECT_NE(message.find("extensions.NIMBUS_participating_media.volume"), std::string::npos) << message;
            EXPECT_NE(message.find("raymarch"), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

TEST_F(VolumeScenes, EveryVolumeSceneStaysFiniteInBothModels) {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(NIMBUS_TEST_DATA_DIR) / "volume_scenes")) {
        if (entry.path().extension() != ".gltf") continue;
        for (const auto model : {assets::Scattering::Single, assets::Scattering::Multiple}) {
            SCOPED_TRACE(entry.path().filename().string() + (model == assets::Scattering::Multiple ? " multiple" : " single"));
            sandbox::Session session({.scene = entry.path(), .settings = {"mode=raymarch"}, .scattering = model});
            const assets::RgbImage image = session.renderRealtime(64, 36);
            EXPECT_EQ(countNonfinite(image), 0u);
            EXPECT_EQ(context().takeGlErrors().count, 0u);
        }
        ++scenes;
    }
    EXPECT_GE(scenes, 9);
}

// Albedo 1 at τ 10⁴ across: every path must end (roulette), and the image is finite.
TEST_F(VolumeScenes, ADenseWhiteBoxEndsInTheReference) {
    sandbox::Session session(raymarch("dense_white_box", assets::Scattering::Multiple));
    const auto scene = sandbox::makeReferenceScene(session, "", 24, 14);
    ref::ReferenceSettings settings{.width = 24, .height = 14, .spp = 4, .scattering = assets::Scattering::Multiple, .progress = false};
    ref::ReferenceStats stats;
    const assets::RgbImage image = ref::ReferenceRenderer(scene->inputs, settings).render(&stats);
    for (const float v : image.rgb) EXPECT_TRUE(std::isfinite(v));
    std::printf("[ measured ] dense_white_box reference 24x14 at 4 paths: %.1f s\n", stats.seconds);
}

}  // namespace
}  // namespace nimbus::test::media
