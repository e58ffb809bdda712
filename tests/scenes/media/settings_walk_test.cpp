// Every setting honoured or refused: every key `sandbox settings` lists, in every mode and tier,
// set to each of a few values its declaration allows. For each key, mode and tier either some
// value changes the frame, or the session refuses the key in one line saying it has no effect
// there. Never silently ignored. The keys and tiers come from the declarations, so a key added
// later is walked too; a mode added later fails EveryDeclaredModeIsWalked until it is listed.
//
// The frames are of a wing through a cloud, which shows every key's effect but those whose
// declaration says they need more of a scene (SettingSpec::showsWith: a lamp inside the medium, a
// reduced media target, a point light); those may show it in the other scenes: a lamp inside a
// medium, a wing seen close, whose billboards are large enough for media_scale=auto to reduce, and
// a campfire, whose point light casts the rocks' shadows. A key that shows only
// after the camera moves (kShowsWithMovingCamera) is judged on a second frame, drawn after one
// through the camera turned half a degree; one that shows only after the medium moves
// (kShowsWithMovingMedium), on a second frame drawn after its clouds moved by a centimetre.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "media_test_support.h"
#include "nimbus/base/error.h"
#include "nimbus/base/settings.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/render/render_plugin.h"

namespace nimbus::test::media {
namespace {

constexpr int kWidth = 96, kHeight = 54;

struct WalkScene {
    std::string name;
    std::shared_ptr<const assets::Scene> scene;
};

std::vector<WalkScene> walkScenes() {
    // A wing through a cloud (soft particles, block seams, multiple scattering), a lamp inside a
    // medium (exact_near_lamps, lamp slices), a wing seen from close enough that
    // media_scale=auto reduces the target at this size (the upsampling keys), and a point light
    // whose cube faces hold rocks' shadows (point_shadow_scale).
    return {{"cumulus_aircraft", std::make_shared<const assets::Scene>(assets::loadScene(contentScene("cumulus_aircraft")))},
            {"unseen_point_inside_dense", std::make_shared<const assets::Scene>(assets::loadScene(mediaScene("unseen_point_inside_dense")))},
            {"wing_close", std::make_shared<const assets::Scene>(assets::loadScene(mediaScene("wing_close")))},
            {"campfire", std::make_shared<const assets::Scene>(assets::loadScene(contentScene("campfire")))}};
}

// The declarations a session makes (what `sandbox settings` lists).
Settings declarations() {
    ecs::App app;
    app.insertResource<Settings>();
    app.addPlugin<render::RenderPlugin>();
    app.addPlugin<nimbus::media::ecs::MediaPlugin>();
    return app.resource<Settings>();
}

// The values a key is tried at, in order until one changes the frame: both booleans, every
// word, and for a range its minimum, a value well inside it (the geometric middle) and its
// maximum (last: the costliest to render).
std::vector<std::string> candidates(const SettingSpec& spec) {
    std::vector<std::string> out = spec.words;
    switch (spec.type) {
        case SettingType::Boolean: return {"on", "off"};
        case SettingType::Choice: return out;
        case SettingType::Integer:
        case SettingType::Number: {
            const double middle = spec.min > 0.0 ? std::sqrt(spec.min * spec.max) : 0.5 * (spec.min + spec.max);
            const double inside = spec.type == SettingType::Integer ? std::round(middle) : middle;
            out.push_back(formatSettingNumber(spec.min));
            if (inside != spec.min) out.push_back(formatSettingNumber(inside));
            if (spec.max != inside) out.push_back(formatSettingNumber(spec.max));
            return out;
        }
    }
    return out;
}

bool sameImage(const assets::RgbImage& a, const assets::RgbImage& b) {
    if (a.width != b.width || a.height != b.height) return false;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            if (a.at(x, y) != b.at(x, y)) return false;
    return true;
}

// One test per mode, so each stays well inside the suite's timeout. The list is checked against
// the declarations (EveryDeclaredModeIsWalked): they cannot be read while tests are registered.
const std::vector<std::string> kWalkedModes{"particles", "blocks", "raymarch", "sheets", "billboards"};

// What moves between the two frames of a key whose effect shows only then (SettingSpec::showsWith).
enum class Motion { None, Camera, Medium };

Motion motionOf(const SettingSpec& spec) {
    if (spec.showsWith == kShowsWithMovingCamera) return Motion::Camera;
    if (spec.showsWith == kShowsWithMovingMedium) return Motion::Medium;
    return Motion::None;
}

class SettingsWalk : public GlSceneTest, public ::testing::WithParamInterface<std::string> {
protected:
    // The frame of `scene` with `settings`, or the refusal's text.
    struct Outcome {
        bool refused = false;
        std::string reason;
        assets::RgbImage image;
    };
    // With `sessionOnly`, a session that is not refused is not rendered either (an empty image).
    // With `motion`, the frame follows one through the camera turned by half a degree, or one
    // before the clouds moved.
    Outcome render(const WalkScene& scene, const std::vector<std::string>& settings, bool sessionOnly = false,
                   Motion motion = Motion::None) {
        sandbox::SessionOptions options;
        options.settings = settings;
        Outcome out;
        try {
            auto session = std::make_unique<sandbox::Session>(scene.scene, options);
            if (sessionOnly) return out;
            if (previous_) session->adoptRenderers(*previous_);  // the programs compiled once
            ecs::World& world = session->app().world();
            if (motion == Motion::Camera) {
                glm::dmat4& camera = world.get<scene::Transform>(nodeEntity(world, "main")).world;
                const glm::dmat4 start = camera;
                camera = glm::rotate(glm::dmat4(1.0), glm::radians(0.5), glm::dvec3(0.0, 1.0, 0.0)) * start;
                (void)session->renderRealtime(kWidth, kHeight);
                camera = start;
            } else if (motion == Motion::Medium) {
                (void)session->renderRealtime(kWidth, kHeight);
                world.view<nimbus::media::ecs::ParticleCloud>().each([&](ecs::Entity e, const nimbus::media::ecs::ParticleCloud&) {
                    glm::dmat4& node = world.get<scene::Transform>(e).world;
                    node = glm::translate(glm::dmat4(1.0), glm::dvec3(0.01, 0.0, 0.0)) * node;
                });
            }
            out.image = session->renderRealtime(kWidth, kHeight);
            previous_ = std::move(session);
        } catch (const InputError& e) {
            out.refused = true;
            out.reason = e.what();
        }
        return out;
    }

    std::unique_ptr<sandbox::Session> previous_;
};

TEST_P(SettingsWalk, EveryKeyInEveryTierChangesTheFrameOrIsRefused) {
    const Settings declared = declarations();
    const SettingSpec* qualitySpec = declared.find("quality");
    ASSERT_NE(qualitySpec, nullptr);
    const std::vector<WalkScene> scenes = walkScenes();

    std::map<std::string, std::string> table;  // "key" → one cell per tier
    std::vector<std::string> silent;
    const std::string& mode = GetParam();
    for (const std::string& tier : qualitySpec->words) {
        const std::vector<std::string> base = {"mode=" + mode, "quality=" + tier};
        std::vector<assets::RgbImage> baselines;
        std::map<Motion, std::vector<assets::RgbImage>> movingBaselines;  // made when a key first needs them
        for (const WalkScene& scene : scenes) {
            const Outcome b = render(scene, base);
            ASSERT_FALSE(b.refused) << b.reason;
            const Outcome again = render(scene, base);
            ASSERT_TRUE(sameImage(b.image, again.image)) << scene.name << " " << mode << " " << tier << ": frames must repeat";
            baselines.push_back(b.image);
        }
        for (const SettingSpec& spec : declared.declarations()) {
            if (spec.key == "mode" || spec.key == "quality") continue;
            // Refused with one value, refused with all (whether a key acts is not a matter of
            // its value); else the values are tried until the frame of some scene changes.
            int refusals = 0, tries = 0;
            bool changed = false;
            std::string reason;
            const Motion motion = motionOf(spec);
            if (motion != Motion::None && movingBaselines[motion].empty())
                for (const WalkScene& scene : scenes) movingBaselines[motion].push_back(render(scene, base, false, motion).image);
            for (const std::string& value : candidates(spec)) {
                std::vector<std::string> settings = base;
                settings.push_back(spec.key + "=" + value);
                const std::size_t shownIn = spec.showsWith.empty() ? 1 : scenes.size();
                for (std::size_t s = 0; s < shownIn && !changed; ++s) {
                    const Outcome o = render(scenes[s], settings, refusals > 0, motion);
                    ++tries;
                    if (o.refused) {
                        ++refusals;
                        reason = o.reason;
                        EXPECT_EQ(reason.find('\n'), std::string::npos) << reason;
                        EXPECT_NE(reason.find("no effect"), std::string::npos) << spec.key << "=" << value << ": " << reason;
                        EXPECT_NE(reason.find(spec.key), std::string::npos) << reason;
                    } else {
                        changed = !sameImage(o.image, motion != Motion::None ? movingBaselines[motion][s] : baselines[s]);
                    }
                }
                if (changed) break;
            }
            const std::string where = spec.key + " in mode " + mode + ", tier " + tier;
            if (refusals > 0) {
                EXPECT_EQ(refusals, tries) << where << ": refused for some values only: " << reason;
                EXPECT_TRUE(reason.find("mode " + mode) != std::string::npos || reason.find("tier " + tier) != std::string::npos ||
                            reason.find("model") != std::string::npos)
                    << where << ": the refusal names the mode or tier: " << reason;
            }
            const char* cell = refusals > 0 ? "refused" : changed ? "changes" : "SILENT";
            table[spec.key] += std::string(table[spec.key].empty() ? "" : " ") + cell;
            if (refusals == 0 && !changed) silent.push_back(where);
        }
    }
    std::string header = "key \\ mode.tier:";
    for (const std::string& tier : qualitySpec->words) header += " " + GetParam() + "." + tier;
    std::printf("%s\n", header.c_str());
    for (const auto& [key, cells] : table) std::printf("%-20s %s\n", key.c_str(), cells.c_str());
    for (const std::string& s : silent) ADD_FAILURE() << s << ": silently ignored (neither changes the frame nor is refused)";
}

INSTANTIATE_TEST_SUITE_P(EveryMode, SettingsWalk, ::testing::ValuesIn(kWalkedModes),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

class SettingsWalkModes : public GlSceneTest {};

TEST_F(SettingsWalkModes, EveryDeclaredModeIsWalked) {
    const Settings declared = declarations();
    const SettingSpec* spec = declared.find("mode");
    ASSERT_NE(spec, nullptr);
    EXPECT_EQ(spec->words, kWalkedModes);
}

}  // namespace
}  // namespace nimbus::test::media
