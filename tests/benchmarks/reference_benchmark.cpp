// The reference renderer's cost on a typical frame: 640×360, a seeded random cloud of 8000 particles
// over a ground plane under a sun (goal: <= 60 s on the 2-core build machine). Not a test: it is
// built with NIMBUS_BUILD_BENCHMARKS and run by hand:
//   build/<dir>/bin/nimbus_reference_benchmark [--benchmark_filter=...]
// Size and particle count can be overridden for quick looks: NIMBUS_BENCH_SIZE=WxH, NIMBUS_BENCH_PARTICLES=N.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "nimbus/assets/scene_queries.h"
#include "nimbus/media/reference/reference_renderer.h"

namespace {

using namespace nimbus;

struct CloudScene {
    assets::Scene scene;
    std::vector<glm::dmat4> world;
    media::ParticleSet particles;
    assets::ResolvedCamera camera;
    std::vector<assets::ResolvedLight> lights;
};

// A cumulus-like ellipsoid of particles (denser towards the middle) 6 m above a 200 m ground quad.
CloudScene makeCloudScene(std::size_t count) {
    CloudScene c;
    assets::Material ground;
    ground.baseColorFactor = {0.35f, 0.33f, 0.3f, 1.0f};
    c.scene.materials.push_back(ground);
    assets::Primitive quad;
    quad.positions = {{-100, 0, 100}, {100, 0, 100}, {100, 0, -100}, {-100, 0, -100}};
    quad.normals.assign(4, glm::vec3(0, 1, 0));
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.material = 0;
    quad.boundsMin = {-100, 0, -100};
    quad.boundsMax = {100, 0, 100};
    c.scene.meshes.push_back({"ground", {quad}});
    assets::Node node;
    node.mesh = 0;
    c.scene.nodes.push_back(node);
    c.scene.rootNodes = {0};
    c.scene.environment.background = {0.35f, 0.55f, 0.9f};
    c.scene.environment.ambient = {0.12f, 0.16f, 0.25f};
    c.world = assets::computeWorldTransforms(c.scene, 0.0);

    media::Medium cloud;
    cloud.albedo = glm::vec3(0.95f);
    cloud.g = 0.6f;
    std::mt19937 rng(20240611u);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const glm::dvec3 centre(0.0, 7.0, 0.0), radii(12.0, 4.5, 8.0);
    while (c.particles.size() < count) {
        const double z = u(rng), y = u(rng), x = u(rng);  // in sequence: the same cloud from every compiler
        const glm::dvec3 q(x, y, z);
        const double r2 = glm::dot(q, q);
        if (r2 > 1.0) continue;
        const float radius = static_cast<float>(1.4 + 0.6 * u(rng));
        const float sigma = static_cast<float>(0.12 * (1.0 - 0.6 * r2) * (1.0 + 0.3 * u(rng)));
        c.particles.push(centre + q * radii, radius, sigma, cloud);
    }

    c.camera.name = "bench";
    c.camera.params.yfov = 0.75;
    c.camera.params.znear = 0.1;
    c.camera.world = glm::inverse(glm::lookAt(glm::dvec3(-6.0, 4.0, 32.0), glm::dvec3(0.0, 6.0, 0.0), glm::dvec3(0, 1, 0)));
    assets::ResolvedLight sun;
    sun.name = "sun";
    sun.params.type = assets::LightType::Directional;
    sun.params.intensity = 3.0f;
    sun.params.color = {1.0f, 0.95f, 0.85f};
    sun.direction = glm::normalize(glm::dvec3(0.5, -1.0, -0.35));
    c.lights = {sun};
    return c;
}

void BM_ReferenceCloud(benchmark::State& state) {
    int width = 640, height = 360;
    std::size_t count = 8000;
    if (const char* s = std::getenv("NIMBUS_BENCH_SIZE")) std::sscanf(s, "%dx%d", &width, &height);
    if (const char* s = std::getenv("NIMBUS_BENCH_PARTICLES")) count = std::strtoul(s, nullptr, 10);
    const CloudScene c = makeCloudScene(count);
    media::reference::ReferenceInputs in;
    in.scene = &c.scene;
    in.world = &c.world;
    in.camera = c.camera;
    in.lights = c.lights;
    in.particles = &c.particles;
    media::reference::ReferenceSettings settings;
    settings.scattering = assets::Scattering::Single;  // today's real-time model
    settings.width = width;
    settings.height = height;
    settings.progress = true;
    media::reference::ReferenceStats stats;
    for (auto _ : state) {
        const assets::RgbImage image = media::reference::renderReference(in, settings, &stats);
        benchmark::DoNotOptimize(image.rgb.data());
        state.SetIterationTime(stats.seconds);
        if (const char* out = std::getenv("NIMBUS_BENCH_OUT")) assets::writeImage(out, image);
    }
    state.counters["seconds"] = stats.seconds;
    state.counters["evaluations_per_pixel"] = static_cast<double>(stats.evaluations) / (width * height);
    state.counters["unconverged_pixels"] = static_cast<double>(stats.unconvergedPixels);
    state.counters["particles"] = static_cast<double>(count);
    state.SetLabel(std::to_string(width) + "x" + std::to_string(height));
}
BENCHMARK(BM_ReferenceCloud)->Unit(benchmark::kSecond)->Iterations(1)->UseManualTime();

}  // namespace

BENCHMARK_MAIN();
