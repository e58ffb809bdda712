#include "nimbus/media/reference/reference_renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <stdexcept>
#include <thread>

#include <glm/gtx/component_wise.hpp>

#include "light_transport.h"
#include "medium_quadrature.h"
#include "nimbus/assets/light_model.h"
#include "nimbus/assets/fog.h"
#include "nimbus/assets/material_sampling.h"
#include "nimbus/base/progress.h"
#include "nimbus/media/optics.h"
#include "nimbus/media/particle_bvh.h"
#include "nimbus/media/reference/camera_rays.h"
#include "nimbus/raycast/mesh_raycaster.h"
#include "scattering_paths.h"
#include "view_ray_medium.h"

namespace nimbus::media::reference {
namespace {

constexpr int kTileSize = 16;


// Per-thread working memory, reused from ray to ray.
struct Scratch {
    ViewRayMedium medium;
    MediumQuadrature quadrature;
    std::vector<double> weights;
    std::vector<double> cuts;
    ViewRayMedium flight;  // a path's flights
    std::vector<double> pathWeights;
};

// Each pixel's paths draw from a stream of their own (PathRandom), independent of threads.
constexpr int kMaxSpp = 1 << 20;

// Where along origin + t·dir the in-scattered light of a point or spot light peaks: its closest
// approach t_l, and t_l ± b, ± 4b, ± 16b around it (b the ray's distance from the light), so that the
// quadrature's first intervals resolve the 1/(b² + (t − t_l)²) spike and its shoulders.
void lightCuts(const std::vector<assets::ResolvedLight>& lights, const glm::dvec3& origin, const glm::dvec3& dir,
               std::vector<double>& cuts) {
    cuts.clear();
    for (const assets::ResolvedLight& light : lights) {
        if (light.params.type == assets::LightType::Directional) continue;
        const glm::dvec3 toLight = light.position - origin;
        const double tl = glm::dot(toLight, dir);
        const double b = glm::length(toLight - tl * dir);
        cuts.push_back(tl);
        for (double k : {1.0, 4.0, 16.0}) {
            cuts.push_back(tl - k * b);
            cuts.push_back(tl + k * b);
        }
    }
}

}  // namespace

struct ReferenceRenderer::Impl {
    ReferenceInputs inputs;
    ReferenceSettings settings;
    ParticleSet noParticles;
    std::vector<Volume> noVolumes;
    const ParticleSet* particles = nullptr;
    const std::vector<Volume>* volumes = nullptr;
    bool multiple = false;                 // the model, from the scene or the settings
    std::unique_ptr<ScatteringPaths> paths;  // multiple scattering with a medium
    ParticleBvh bvh;
    std::unique_ptr<raycast::MeshRaycaster> meshes;
    std::unique_ptr<assets::MaterialSampler> materials;
    std::unique_ptr<LightTransport> light;
    CameraFrame frame;
    glm::dvec3 background{0.0}, ambient{0.0};
    double fogReach = 0.0;  // how far background rays see fog
    double floor = 0.0;

    RayRadiance trace(const glm::dvec3& origin, const glm::dvec3& dir, double meshNear, double meshFar, std::uint64_t stream,
                      Scratch& scratch) const;
    // The paths' mean and standard error for one camera ray whose medium scratch.medium holds.
    void tracePaths(const glm::dvec3& origin, const glm::dvec3& dir, std::uint64_t stream, Scratch& scratch, RayRadiance& out) const;
    bool doubleSided(int material) const {
        return material >= 0 && static_cast<std::size_t>(material) < inputs.scene->materials.size() &&
               inputs.scene->materials[static_cast<std::size_t>(material)].doubleSided;
    }
};

ReferenceRenderer::ReferenceRenderer(const ReferenceInputs& inputs, const ReferenceSettings& settings)
    : impl_(std::make_unique<Impl>()) {
    if (!inputs.scene || !inputs.world) throw std::invalid_argument("reference: inputs need a scene and its world transforms");
    if (settings.width <= 0 || settings.height <= 0) throw std::invalid_argument("reference: image size must be positive");
    if (!(settings.tolerance > 0.0)) throw std::invalid_argument("reference: tolerance must be > 0");
    if (settings.spp < 1 || settings.spp > kMaxSpp) throw std::invalid_argument("reference: spp must be in 1..2^20");
    Impl& m = *impl_;
    m.inputs = inputs;
    m.settings = settings;
    m.particles = inputs.particles ? inputs.particles : &m.noParticles;
    m.volumes = inputs.volumes ? inputs.volumes : &m.noVolumes;
    m.bvh.build(*m.particles);
    m.meshes = std::make_unique<raycast::MeshRaycaster>(*inputs.scene, *inputs.world);
    m.materials = std::make_unique<assets::MaterialSampler>(*inputs.scene);
    m.background = glm::dvec3(inputs.scene->environment.background);
    m.ambient = glm::dvec3(inputs.scene->environment.ambient);
    const assets::Scattering model = settings.scattering.value_or(inputs.scene->environment.scattering);
    m.multiple = model == assets::Scattering::Multiple && !(m.particles->empty() && m.volumes->empty());
    // In the multiple model the ambient is an environment the paths bring in; meshes keep it unshadowed.
    m.light = std::make_unique<LightTransport>(m.inputs.lights, *m.meshes, m.bvh, *m.particles, *m.volumes,
                                               m.multiple ? glm::dvec3(0.0) : m.ambient, m.ambient);
    if (m.multiple) m.paths = std::make_unique<ScatteringPaths>(*m.light, *m.meshes, m.bvh, *m.particles, m.ambient);
    m.frame = makeCameraFrame(inputs.camera, settings.width, settings.height);
    m.fogReach = assets::fogBackgroundDistance(inputs.scene->environment.fog, inputs.camera.params.zfar);

    // The scene's radiance scale, for the quadrature's absolute floor (reference_renderer.h).
    double scale = std::max(glm::compMax(m.background), glm::compMax(m.ambient));
    for (const glm::vec3& e : m.particles->emission) scale = std::max(scale, static_cast<double>(std::max({e.x, e.y, e.z})));
    glm::dvec3 centre(0.0);
    if (!m.bvh.empty()) {
        centre = 0.5 * (m.bvh.boundsMin() + m.bvh.boundsMax());
    } else if (!m.meshes->empty()) {
        centre = m.meshes->origin();
    }
    for (const assets::ResolvedLight& l : m.inputs.lights)
        scale = std::max(scale, glm::compMax(assets::sampleLight(l, centre).irradiance) / kPi);
    m.floor = settings.tolerance * 1e-3 * scale;
}

ReferenceRenderer::~ReferenceRenderer() = default;

double ReferenceRenderer::absoluteFloor() const { return impl_->floor; }

void ReferenceRenderer::Impl::tracePaths(const glm::dvec3& origin, const glm::dvec3& dir, std::uint64_t stream, Scratch& scratch,
                                         RayRadiance& out) const {
    const assets::Fog& fog = inputs.scene->environment.fog;
    glm::dvec3 sum(0.0), squares(0.0);
    for (int s = 0; s < settings.spp; ++s) {
        PathRandom random(settings.seed, stream * static_cast<std::uint64_t>(kMaxSpp) + static_cast<std::uint64_t>(s));
        const PathSample path = paths->sample(origin, dir, scratch.medium, random, scratch.flight, scratch.pathWeights);
        glm::dvec3 value = path.radiance;
        // Fog sees the scattered light where the path left the camera ray; its colour is the quadrature's.
        if (fog.mode != assets::FogMode::None) value *= assets::fogFactor(fog, origin.y, dir.y, path.firstDistance);
        sum += value;
        squares += value * value;
        out.evaluations += path.vertices;
    }
    const double n = settings.spp;
    out.paths = sum / n;
    const glm::dvec3 variance = glm::max(squares / n - out.paths * out.paths, glm::dvec3(0.0)) * (n / std::max(n - 1.0, 1.0));
    out.standardError = glm::sqrt(variance / n);
    out.inScattered += out.paths;
    out.radiance += out.paths;
}

RayRadiance ReferenceRenderer::Impl::trace(const glm::dvec3& origin, const glm::dvec3& dir, double meshNear,
                                           double meshFar, std::uint64_t stream, Scratch& scratch) const {
    RayRadiance out;
    const std::optional<raycast::MeshHit> hit = meshes->closestHit(origin, dir, meshNear, meshFar);
    out.hitMesh = hit.has_value();
    out.distance = hit ? hit->distance : meshFar;

    scratch.medium.build(bvh, *particles, origin, dir, out.distance, *volumes);
    out.opticalDepth = scratch.medium.totalOpticalDepth();
    out.transmittance = transmittance(out.opticalDepth);

    // Fog (scene-format.md §2.1): what lies at distance t is seen as f(t)·L + (1 − f(t))·colour, the
    // surface at its distance (the background at the fog's reach) and the medium at every sample.
    const assets::Fog& fog = inputs.scene->environment.fog;
    const bool fogged = fog.mode != assets::FogMode::None;
    glm::dvec3 behind(0.0);  // T(0,d) L_s; skipped when nothing of it gets through
    if (out.transmittance > 0.0) {
        out.surface = hit ? light->surfaceRadiance(*hit, dir, doubleSided(hit->material), materials->sample(hit->material, hit->attributes())) : background;
        if (fogged)
            out.surface = assets::applyFog(fog, assets::fogFactor(fog, origin.y, dir.y, hit ? hit->distance : fogReach), out.surface);
        behind = out.transmittance * out.surface;
    }
    out.radiance = behind;
    if (scratch.medium.empty()) return out;

    QuadratureSettings q;
    q.tolerance = settings.tolerance;
    q.absoluteFloor = floor;
    const ViewRayMedium& medium = scratch.medium;
    std::vector<double>& weights = scratch.weights;
    const SourceFunction source = [&](const RaySample& s) {
        const glm::dvec3 j = light->mediumSource(origin, dir, medium, s.piece, s.t, weights);
        return fogged ? assets::applyFog(fog, assets::fogFactor(fog, origin.y, dir.y, s.t), j) : j;
    };
    lightCuts(inputs.lights, origin, dir, scratch.cuts);
    const QuadratureResult r = scratch.quadrature.integrate(medium, source, behind, q, scratch.cuts);
    out.inScattered = r.value;
    out.radiance += r.value;
    out.evaluations = r.evaluations;
    out.converged = r.converged;
    if (paths) tracePaths(origin, dir, stream, scratch, out);
    return out;
}

RayRadiance ReferenceRenderer::traceRay(const glm::dvec3& origin, const glm::dvec3& dir, double meshNear, double meshFar,
                                        std::uint64_t stream) const {
    Scratch scratch;
    return impl_->trace(origin, glm::normalize(dir), meshNear, meshFar, stream, scratch);
}

RayRadiance ReferenceRenderer::tracePixel(int x, int y) const {
    const CameraRay ray = cameraRay(impl_->frame, x, y);
    Scratch scratch;
    return impl_->trace(ray.origin, ray.direction, ray.meshNear, ray.meshFar,
                        static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(impl_->settings.width) + static_cast<std::uint64_t>(x), scratch);
}

bool ReferenceRenderer::multiple() const { return impl_->multiple; }

namespace {

// What one worker counted over its tiles.
struct Tally {
    std::size_t evaluations = 0, unconverged = 0, paths = 0;
    double standardError = 0.0, radiance = 0.0;  // Σ over its pixels, of luminance
};

double luminanceOf(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

}  // namespace

assets::RgbImage ReferenceRenderer::render(ReferenceStats* stats, assets::RgbImage* standardError) const {
    const Impl& m = *impl_;
    const auto start = std::chrono::steady_clock::now();
    const int width = m.settings.width, height = m.settings.height;
    assets::RgbImage image(width, height);
    if (standardError) *standardError = assets::RgbImage(width, height);
    const int tilesX = (width + kTileSize - 1) / kTileSize, tilesY = (height + kTileSize - 1) / kTileSize;
    const int tiles = tilesX * tilesY;
    int threads = m.settings.threads > 0 ? m.settings.threads : static_cast<int>(std::thread::hardware_concurrency());
    threads = std::clamp(threads, 1, std::max(1, tiles));

    std::unique_ptr<ProgressBar> progress;
    if (m.settings.progress) progress = std::make_unique<ProgressBar>("reference", static_cast<std::size_t>(tiles));
    std::atomic<int> nextTile{0};
    if (m.settings.watch) m.settings.watch->tilesTotal.store(tiles);
    std::vector<Tally> tally(static_cast<std::size_t>(threads));
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(threads));

    // Tiles are handed out dynamically, but every pixel is computed from the inputs alone and written
    // to its own place (its paths from its own random stream), so the image does not depend on which
    // thread did what.
    auto pixel = [&](int x, int y, Scratch& scratch, Tally& t) {
        const CameraRay ray = cameraRay(m.frame, x, y);
        const std::uint64_t stream = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(width) + static_cast<std::uint64_t>(x);
        const RayRadiance r = m.trace(ray.origin, ray.direction, ray.meshNear, ray.meshFar, stream, scratch);
        image.set(x, y, glm::vec3(r.radiance));
        if (standardError) standardError->set(x, y, glm::vec3(r.standardError));
        t.evaluations += static_cast<std::size_t>(r.evaluations);
        t.unconverged += r.converged ? 0 : 1;
        t.paths += m.paths ? static_cast<std::size_t>(m.settings.spp) : 0;
        t.standardError += luminanceOf(r.standardError);
        t.radiance += luminanceOf(r.radiance);
    };
    auto work = [&](std::size_t worker) {
        try {
            Scratch scratch;
            for (int tile = nextTile.fetch_add(1); tile < tiles; tile = nextTile.fetch_add(1)) {
                if (m.settings.watch && m.settings.watch->cancel.load()) break;
                const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
                for (int y = y0; y < std::min(y0 + kTileSize, height); ++y)
                    for (int x = x0; x < std::min(x0 + kTileSize, width); ++x) pixel(x, y, scratch, tally[worker]);
                if (progress) progress->advance();
                if (m.settings.watch) m.settings.watch->tilesDone.fetch_add(1);
            }
        } catch (...) {
            errors[worker] = std::current_exception();
            nextTile.store(tiles);
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work, static_cast<std::size_t>(t));
    work(0);
    for (std::thread& t : pool) t.join();
    if (progress) progress->finish();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);

    if (stats) {
        *stats = ReferenceStats{};
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats->multiple = m.multiple;
        for (const Tally& t : tally) {
            stats->evaluations += t.evaluations;
            stats->unconvergedPixels += t.unconverged;
            stats->paths += t.paths;
            stats->meanStandardError += t.standardError;
            stats->meanRadiance += t.radiance;
        }
        const double pixels = static_cast<double>(width) * height;
        stats->meanStandardError /= pixels;
        stats->meanRadiance /= pixels;
    }
    return image;
}

assets::RgbImage renderReference(const ReferenceInputs& inputs, const ReferenceSettings& settings, ReferenceStats* stats,
                                 assets::RgbImage* standardError) {
    return ReferenceRenderer(inputs, settings).render(stats, standardError);
}

}  // namespace nimbus::media::reference
