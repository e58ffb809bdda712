// glTF materials rendered in real time against the judge (docs/scene-format.md §4.1): the content
// scene courtyard.gltf (every feature beside smoke), a MetalRoughSpheres equivalent, and Khronos
// BoxVertexColors and BoxTextured. Both renderers share one Session (same load, same particles);
// the medium is compared in the single-scattering model, so the judge is exact and the images
// differ only by what the real-time approximations do.
//
// "Away from edges": a pixel is left out where the reference's 3×3 neighbourhood jumps by more
// than half the larger luminance (a silhouette, a cutout's border, a shadow's edge: the
// rasteriser and the judge may put those a pixel apart). rel-RMSE = RMSE of linear RGB over the
// other pixels / their mean reference luminance. Bound: 2 %, the issue's.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <limits>

#include <nlohmann/json.hpp>

#include "media/media_test_support.h"
#include "process.h"

namespace nimbus::test::media {
namespace {

constexpr int kWidth = 192, kHeight = 108;
constexpr double kBound = 0.02;

std::filesystem::path khronos(const std::string& name) {
    return std::filesystem::path(NIMBUS_TEST_DATA_DIR) / "khronos" / name / (name + ".gltf");
}

// A copy of an embedded .gltf whose samplers minify as they magnify, without mipmaps: the judge
// takes one bilinear tap per pixel (magFilter), so only then do the two renderers filter alike
// where a texture is minified.
std::filesystem::path withoutMipmaps(const std::filesystem::path& file, const TempFolder& folder) {
    std::ifstream in(file);
    nlohmann::json gltf = nlohmann::json::parse(in);
    for (auto& sampler : gltf["samplers"]) sampler["minFilter"] = sampler.value("magFilter", 9729);
    const std::filesystem::path out = folder / file.filename();
    std::ofstream(out) << gltf.dump();
    return out;
}

struct AwayFromEdges {
    double relRmse = 0.0;
    double edgeFraction = 0.0;  // of the image's pixels, left out
    std::size_t compared = 0;
};

AwayFromEdges compareAwayFromEdges(const assets::RgbImage& realtime, const assets::RgbImage& reference) {
    AwayFromEdges out;
    double squares = 0.0, meanLuminance = 0.0;
    std::size_t edges = 0;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            const double centre = luminance(reference.at(x, y));
            bool edge = false;
            for (int dy = -1; dy <= 1 && !edge; ++dy)
                for (int dx = -1; dx <= 1 && !edge; ++dx) {
                    const int nx = std::clamp(x + dx, 0, reference.width - 1), ny = std::clamp(y + dy, 0, reference.height - 1);
                    const double other = luminance(reference.at(nx, ny));
                    edge = std::abs(other - centre) > 0.5 * std::max({other, centre, 1e-6});
                }
            if (edge) {
                ++edges;
                continue;
            }
            const glm::vec3 d = realtime.at(x, y) - reference.at(x, y);
            squares += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
            meanLuminance += centre;
            ++out.compared;
        }
    const double n = static_cast<double>(std::max<std::size_t>(out.compared, 1));
    out.relRmse = std::sqrt(squares / (3.0 * n)) / std::max(meanLuminance / n, 1e-12);
    out.edgeFraction = static_cast<double>(edges) / (static_cast<double>(reference.width) * reference.height);
    return out;
}

class Materials : public GlSceneTest {
protected:
    // `scale` enlarges the image where a texture would otherwise be minified: the judge takes one
    // bilinear tap per pixel, the rasteriser filters a mipmapped texture over the pixel.
    AwayFromEdges check(const std::filesystem::path& scene, double time, const char* label, int scale = 1, double bound = kBound) {
        const FramePair pair = renderBoth(scene, time, scale * kWidth, scale * kHeight);
        const AwayFromEdges m = compareAwayFromEdges(pair.realtime, pair.reference);
        std::printf("[ measured ] %s rel_rmse away from edges=%.4f (bound %.2f), %.1f%% of the pixels at edges\n", label, m.relRmse, bound,
                    100.0 * m.edgeFraction);
        RecordProperty("rel_rmse_away_from_edges", std::to_string(m.relRmse));
        EXPECT_LE(m.relRmse, bound) << label;
        EXPECT_LT(m.edgeFraction, 0.3) << label << ": so many edges that the comparison says little";
        lastRealtime = pair.realtime;
        lastReference = pair.reference;
        return m;
    }
    assets::RgbImage lastRealtime, lastReference;
};

TEST_F(Materials, CourtyardMatchesTheReferenceAwayFromEdges) {
    // Textures through KHR_texture_transform and TEXCOORD_1, a MASK fence, metals, COLOR_0, an
    // emissive sign and smoke (make_scenes.py TIMES: 6 s).
    check(contentScene("courtyard"), 6.0, "courtyard");
}

TEST_F(Materials, MetalRoughSpheresMatchTheReferenceAwayFromEdges) {
    check(std::filesystem::path(NIMBUS_TEST_DATA_DIR) / "materials" / "metal_rough_spheres.gltf", 0.0, "metal_rough_spheres");
    // The highlight of the smoothest metal is far brighter than its diffuse neighbours: the BRDF,
    // not Lambert, is being compared.
    float peak = 0.0f;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) peak = std::max(peak, lastReference.at(x, y).x);
    EXPECT_GT(peak, 5.0f);
}

TEST_F(Materials, BoxVertexColorsShowsItsColoursWithoutABlackSide) {
    // No material (glTF's default: white metal, roughness 1) and no light: the default sun and
    // ambient (docs/scene-format.md §4), the colour from COLOR_0 alone.
    check(khronos("BoxVertexColors"), 0.0, "BoxVertexColors");
    int box = 0, coloured = 0, black = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec3 c = lastRealtime.at(x, y);
            if (c == glm::vec3(0.0f)) continue;  // the black background
            ++box;
            const float hi = std::max({c.x, c.y, c.z}), lo = std::min({c.x, c.y, c.z});
            if (hi > 2.0f * lo + 1e-3f) ++coloured;
            if (luminance(c) < 0.02) ++black;
        }
    EXPECT_GT(box, kWidth * kHeight / 10);
    EXPECT_GT(coloured, box / 2) << "the vertex colours show";
    EXPECT_EQ(black, 0) << "no face is pitch black";
}

TEST_F(Materials, BoxTexturedShowsItsTextureWithoutABlackSide) {
    // The texture read the same way up by the rasteriser (GL rows) and the judge (image rows): a
    // flip would put the logo's blue field on its green one and fail the comparison. The file's
    // sampler minifies with NEAREST_MIPMAP_LINEAR, which the judge does not model (21 % at 768×432
    // as written, 0.4 % without mipmaps): the comparison reads the copy without them.
    TempFolder folder;
    check(withoutMipmaps(khronos("BoxTextured"), folder), 0.0, "BoxTextured (no mipmaps)", 2);
    // As written: the same model, filtered differently where minified (measured, no bound).
    check(khronos("BoxTextured"), 0.0, "BoxTextured", 2, std::numeric_limits<double>::infinity());
    int box = 0, black = 0;
    for (int y = 0; y < lastRealtime.height; ++y)
        for (int x = 0; x < lastRealtime.width; ++x) {
            const glm::vec3 c = lastRealtime.at(x, y);
            if (c == glm::vec3(0.0f)) continue;
            ++box;
            if (luminance(c) < 0.02) ++black;
        }
    EXPECT_GT(box, lastRealtime.width * lastRealtime.height / 10);
    EXPECT_EQ(black, 0) << "no face is pitch black";
}

}  // namespace
}  // namespace nimbus::test::media
