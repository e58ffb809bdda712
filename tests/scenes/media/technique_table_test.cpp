// A media mode added through the technique table alone (nimbus/media/technique.h): a technique
// that fills the media layer with a constant radiance and no transmittance, with one setting of
// its own. It shows up in `sandbox settings` and in the unknown-mode error, its setting is parsed
// from --set and validated, and it renders: every pixel is its constant.
#include <gtest/gtest.h>

#include <string>

#include "media_test_support.h"
#include "nimbus/base/error.h"
#include "nimbus/base/settings.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/media/technique.h"
#include "settings_listing.h"

namespace nimbus::test::media {
namespace {

namespace nm = nimbus::media;

struct ConstantSettings {
    float radiance = 0.0f;  // 0: 1
};

class ConstantTechnique final : public nm::MediaTechnique {
public:
    void addLightSlices(gpu::FrameGraph&, nm::GraphFrame&, nm::TechniqueFrame&) override {}
    gpu::ResourceHandle addMedia(gpu::FrameGraph& graph, nm::GraphFrame& context, nm::TechniqueFrame& frame) override {
        const auto own = nm::techniqueSettings<ConstantSettings>(*frame.settings);
        const float c = own.radiance > 0.0f ? own.radiance : 1.0f;
        const gpu::View& v = context.host.camera;
        struct Data {
            gpu::ResourceHandle media;
        };
        frame.report("constant", static_cast<double>(c));
        const auto& data = graph.addPass<Data>(
            "media_constant",
            [&](gpu::PassBuilder& builder, Data& d) { d.media = builder.create("media_color", {GL_TEXTURE_2D, GL_RGBA32F, v.width, v.height, 1, 1}); },
            [c](const gpu::PassResources& r, const Data& d) {
                const float value[4] = {c, c, c, 0.0f};  // radiance c, nothing of the scene behind
                glClearTexImage(r.id(d.media), 0, GL_RGBA, GL_FLOAT, value);
            });
        return data.media;
    }
};

const SettingField<ConstantSettings> kConstantFields[] = {
    {{.key = "constant_radiance", .help = "the radiance every pixel of the layer holds", .type = SettingType::Number, .min = 0.01,
      .max = 100.0, .defaultValue = "1"},
     &setNumber<&ConstantSettings::radiance>},
};

nm::TechniqueTable withConstantMode() {
    nm::TechniqueTable table = nm::builtInTechniques();
    table.add({.name = "constant",
               .help = "a test mode: the media layer filled with one radiance",
               .lightSlices = false,
               .multipleScattering = false,
               .settings = specsOf(kConstantFields),
               .read = [](const Settings& settings, QualityTier) -> std::any {
                   return readFields<ConstantSettings>(settings, kConstantFields, {});
               },
               .create = [] { return std::make_unique<ConstantTechnique>(); }});
    return table;
}

sandbox::SessionOptions constantSession(std::vector<std::string> settings) {
    sandbox::SessionOptions options{contentScene("smoke"), 8.0, std::move(settings)};
    options.techniques = withConstantMode();
    return options;
}

TEST(TechniqueTable, AModeOfItsOwnShowsUpInTheSettingsListAndTheErrors) {
    ecs::App app;
    app.insertResource<Settings>();
    app.addPlugin<nm::ecs::MediaPlugin>(withConstantMode());
    const std::string listing = sandbox::listSettings(app.resource<Settings>());
    EXPECT_NE(listing.find("constant_radiance"), std::string::npos) << listing;
    EXPECT_NE(listing.find("constant: a test mode"), std::string::npos) << listing;
    EXPECT_NE(listing.find("in mode constant"), std::string::npos) << listing;
    Settings settings = app.resource<Settings>();
    settings.set("mode", "bogus");
    try {
        (void)nm::readMediaSettings(settings, app.resource<nm::ecs::MediaTechniques>().table);
        FAIL() << "mode=bogus was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("constant"), std::string::npos) << e.what();
    }
}

TEST(TechniqueTable, AModeIsRegisteredOnceAndItsKeysAreItsOwn) {
    nm::TechniqueTable table = withConstantMode();
    EXPECT_THROW(table.add({.name = "constant"}), std::logic_error);
    EXPECT_THROW(table.add({.name = "other", .settings = specsOf(kConstantFields)}), std::logic_error);
    EXPECT_EQ(table.names().back(), "constant");
}

class ConstantModeTest : public GlSceneTest {};

TEST_F(ConstantModeTest, RendersItsConstantEverywhere) {
    sandbox::Session session(constantSession({"mode=constant", "constant_radiance=0.25"}));
    const assets::RgbImage image = session.renderRealtime(64, 36);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) ASSERT_EQ(image.at(x, y), glm::vec3(0.25f)) << x << "," << y;
    const auto& state = session.app().resource<nm::ecs::MediaRendererState>();
    EXPECT_EQ(state.renderer->stats().mode, "constant");
    EXPECT_EQ(state.renderer->stats().value("constant"), 0.25);
}

TEST_F(ConstantModeTest, ItsSettingIsValidatedLikeAnyOther) {
    try {
        sandbox::Session session(constantSession({"mode=constant", "constant_radiance=500"}));
        FAIL() << "constant_radiance=500 was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("constant_radiance"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("0.01..100"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace nimbus::test::media
