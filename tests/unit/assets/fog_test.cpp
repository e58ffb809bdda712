#include "nimbus/assets/fog.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "nimbus/assets/gltf_file.h"
#include "nimbus/base/error.h"

namespace nimbus::assets {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Fog fog(FogMode mode, double density, double falloff = 0.0, double base = 0.0) {
    Fog f;
    f.mode = mode;
    f.density = density;
    f.falloff = falloff;
    f.base = base;
    f.color = glm::dvec3(0.5, 0.6, 0.7);
    return f;
}

// τ by composite Simpson over the ray, for the height fog's closed form to answer to.
double integratedHeightDepth(const Fog& f, double y0, double dirY, double z) {
    const int n = 20000;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double t = z * i / n, w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += w * f.density * std::exp(-f.falloff * (y0 + t * dirY - f.base));
    }
    return sum * z / (3.0 * n);
}

TEST(Fog, ExpExp2AndLinearAreTheirFormulas) {
    EXPECT_DOUBLE_EQ(fogFactor(fog(FogMode::Exp, 0.1), 0.0, 0.0, 7.0), std::exp(-0.7));
    EXPECT_DOUBLE_EQ(fogFactor(fog(FogMode::Exp2, 0.1), 0.0, 0.0, 7.0), std::exp(-0.49));
    Fog linear = fog(FogMode::Linear, 0.0);
    linear.start = 10.0;
    linear.end = 30.0;
    EXPECT_DOUBLE_EQ(fogFactor(linear, 0.0, 0.0, 5.0), 1.0);
    EXPECT_DOUBLE_EQ(fogFactor(linear, 0.0, 0.0, 25.0), 0.25);
    EXPECT_DOUBLE_EQ(fogFactor(linear, 0.0, 0.0, 40.0), 0.0);
    EXPECT_EQ(fogFactor(linear, 0.0, 0.0, kInf), 0.0);
    EXPECT_EQ(fogFactor(fog(FogMode::Exp, 0.1), 0.0, 0.0, kInf), 0.0);
    EXPECT_EQ(fogFactor(fog(FogMode::Exp, 0.0), 0.0, 0.0, kInf), 1.0);  // no density: no fog, even at infinity
    EXPECT_EQ(fogFactor(fog(FogMode::None, 5.0), 0.0, 0.0, 100.0), 1.0);
}

TEST(Fog, HeightFogMatchesItsIntegralUpDownAndLevel) {
    const Fog f = fog(FogMode::Height, 0.08, 0.3, 2.0);
    for (const double dirY : {-0.6, -0.05, -1e-7, 0.0, 1e-9, 0.02, 0.7})
        for (const double z : {0.5, 12.0, 80.0}) {
            const double expected = integratedHeightDepth(f, 5.0, dirY, z);
            EXPECT_NEAR(heightFogDepth(f, 5.0, dirY, z), expected, 1e-9 * std::max(1.0, expected)) << dirY << " " << z;
        }
}

TEST(Fog, HorizontalRayIsUniformAtItsHeight) {
    const Fog f = fog(FogMode::Height, 0.05, 0.4, 1.0);
    EXPECT_DOUBLE_EQ(heightFogDepth(f, 3.0, 0.0, 20.0), 0.05 * std::exp(-0.4 * 2.0) * 20.0);
    // A falloff of 0 is exp fog.
    EXPECT_DOUBLE_EQ(fogFactor(fog(FogMode::Height, 0.05), 100.0, 0.3, 20.0), fogFactor(fog(FogMode::Exp, 0.05), 0.0, 0.0, 20.0));
}

TEST(Fog, HeightFogAtInfinityAndFarFromTheBase) {
    const Fog f = fog(FogMode::Height, 0.05, 0.5, 0.0);
    EXPECT_NEAR(heightFogDepth(f, 0.0, 0.25, kInf), 0.05 / (0.5 * 0.25), 1e-12);  // looking up: the sky shows through
    EXPECT_EQ(heightFogDepth(f, 0.0, -0.25, kInf), kInf);
    EXPECT_EQ(fogFactor(f, 0.0, 0.0, kInf), 0.0);
    // 1e5 m below the base e^(+k·h) overflows a double; the log form gives f = 0, not NaN.
    EXPECT_EQ(fogFactor(f, -1e5, 0.1, 50.0), 0.0);
    // 1e5 m above it the fog is gone, and looking down from there reaches it only far away.
    EXPECT_EQ(fogFactor(f, 1e5, -0.5, 100.0), 1.0);
    const double far = fogFactor(f, 1e5, -1.0, 1e5 - 1.0);
    EXPECT_TRUE(std::isfinite(far));
    EXPECT_LT(far, 1.0);
}

// The loader refuses every invalid fog with file, object and field.
TEST(Fog, InvalidFogIsRefusedNamingTheField) {
    const auto refusal = [](const nlohmann::json& fogJson) -> std::string {
        nlohmann::json root = {{"asset", {{"version", "2.0"}}},
                               {"extensions", {{"NIMBUS_participating_media", {{"fog", fogJson}}}}}};
        try {
            (void)loadSceneFromMemory(encodeGltf(root, {}, false), "fog.gltf");
        } catch (const InputError& e) {
            return e.what();
        }
        return "(accepted)";
    };
    const std::string where = "fog.gltf: root extension NIMBUS_participating_media: fog.";
    EXPECT_EQ(refusal({{"mode", "exp"}, {"density", -0.1}}).rfind(where + "density", 0), 0u) << refusal({{"mode", "exp"}, {"density", -0.1}});
    EXPECT_EQ(refusal({{"mode", "smog"}}).rfind(where + "mode", 0), 0u);
    EXPECT_EQ(refusal({{"density", 0.1}}).rfind(where + "mode: is required", 0), 0u);
    EXPECT_EQ(refusal({{"mode", "linear"}, {"start", 5.0}}).rfind(where + "end: is required", 0), 0u);
    EXPECT_EQ(refusal({{"mode", "linear"}, {"start", 5.0}, {"end", 5.0}}).rfind(where + "end: must be greater than start", 0), 0u);
    EXPECT_EQ(refusal({{"mode", "exp"}, {"end", -1.0}}).rfind(where + "end", 0), 0u);
    EXPECT_EQ(refusal({{"mode", "height"}, {"falloff", -1.0}}).rfind(where + "falloff", 0), 0u);
    EXPECT_EQ(refusal({{"mode", "exp"}, {"colour", {1, 1, 1}}}).rfind(where + "colour: unknown key", 0), 0u);
    EXPECT_EQ(refusal({{"mode", "exp"}, {"color", {1, -1, 1}}}).rfind(where + "color", 0), 0u);
    EXPECT_EQ(refusal({{"mode", "height"}, {"density", 0.1}, {"base", 2.0}, {"falloff", 0.5}, {"color", {1, 1, 1}}}), "(accepted)");
}

TEST(Fog, LoaderReadsTheFog) {
    nlohmann::json root = {{"asset", {{"version", "2.0"}}},
                           {"extensions", {{"NIMBUS_participating_media",
                                            {{"fog", {{"mode", "linear"}, {"start", 2.0}, {"end", 9.0}, {"color", {0.1, 0.2, 0.3}}}}}}}}};
    const Scene scene = loadSceneFromMemory(encodeGltf(root, {}, false), "fog.gltf");
    const Fog& f = scene.environment.fog;
    EXPECT_EQ(f.mode, FogMode::Linear);
    EXPECT_EQ(f.start, 2.0);
    EXPECT_TRUE(f.hasEnd);
    EXPECT_EQ(f.end, 9.0);
    EXPECT_EQ(f.color, glm::dvec3(0.1, 0.2, 0.3));
    EXPECT_EQ(fogBackgroundDistance(f, 100.0), 9.0);
    Fog noEnd;
    EXPECT_EQ(fogBackgroundDistance(noEnd, 100.0), 100.0);
    EXPECT_EQ(fogBackgroundDistance(noEnd, 0.0), kInf);
}

}  // namespace
}  // namespace nimbus::assets
