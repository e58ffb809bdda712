#include "nimbus/media/vdb/medium_grids.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <system_error>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "nimbus/base/error.h"
#include "nimbus/base/progress.h"
#include "nimbus/media/optics.h"

namespace nimbus::media::vdb {
namespace {

// What a particle or a volume brings to a voxel besides its extinction.
struct Source {
    glm::vec3 albedo{1.0f};
    glm::vec3 emission{0.0f};
    float g = 0.0f;
};

Source sourceOf(const glm::vec3& albedo, const glm::vec3& emission, float g, PhaseFunction phase) {
    return {albedo, emission, phase == PhaseFunction::Rayleigh ? 0.0f : g};  // Rayleigh's mean cosine is 0
}

// Which attributes every source shares (then metadata rather than a grid), and the phase functions.
struct Uniformity {
    bool albedo = true, emission = true, g = true;
    bool any = false, henyeyGreenstein = false, rayleigh = false;
    Source first;

    void see(const Source& s, PhaseFunction phase) {
        (phase == PhaseFunction::Rayleigh ? rayleigh : henyeyGreenstein) = true;
        if (!any) {
            first = s;
            any = true;
            return;
        }
        albedo = albedo && s.albedo == first.albedo;
        emission = emission && s.emission == first.emission;
        g = g && s.g == first.g;
    }
    std::string phase() const { return rayleigh ? (henyeyGreenstein ? "mixed" : "rayleigh") : "henyey-greenstein"; }
};

openvdb::Vec3s toVdb(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// Adds σ-weighted sources to the grids' voxels; the sums become means in normalise().
class Deposit {
public:
    explicit Deposit(MediumGrids& grids) : density_(grids.density->getAccessor()) {
        if (grids.albedo) albedo_.emplace(grids.albedo->getAccessor());
        if (grids.emission) emission_.emplace(grids.emission->getAccessor());
        if (grids.g) g_.emplace(grids.g->getAccessor());
    }

    void add(const openvdb::Coord& c, float s, const Source& src) {
        if (!(s > 0.0f)) return;  // only voxels with medium become active
        density_.setValue(c, density_.getValue(c) + s);
        if (albedo_) albedo_->setValue(c, albedo_->getValue(c) + toVdb(src.albedo) * s);
        if (emission_) emission_->setValue(c, emission_->getValue(c) + toVdb(src.emission) * s);
        if (g_) g_->setValue(c, g_->getValue(c) + src.g * s);
    }

private:
    openvdb::FloatGrid::Accessor density_;
    std::optional<openvdb::Vec3SGrid::Accessor> albedo_, emission_;
    std::optional<openvdb::FloatGrid::Accessor> g_;
};

glm::dvec3 centreOf(const openvdb::Coord& c, double h) { return glm::dvec3(c.x(), c.y(), c.z()) * h; }

// Particle i's kernel at every voxel centre inside its sphere.
void splatParticle(const ParticleSet& p, std::size_t i, double h, Deposit& deposit) {
    const double radius = p.radius[i], sigma = p.sigma[i];
    if (!(radius > 0.0) || !(sigma > 0.0)) return;
    const glm::ivec3 lo(glm::ceil((p.position[i] - radius) / h)), hi(glm::floor((p.position[i] + radius) / h));
    const double invR2 = 1.0 / (radius * radius);
    const Source src = sourceOf(p.albedo[i], p.emission[i], p.g[i], p.phase[i]);
    openvdb::Coord c;
    for (c.z() = lo.z; c.z() <= hi.z; ++c.z())
        for (c.y() = lo.y; c.y() <= hi.y; ++c.y())
            for (c.x() = lo.x; c.x() <= hi.x; ++c.x()) {
                const glm::dvec3 d = centreOf(c, h) - p.position[i];
                const double r2 = glm::dot(d, d) * invR2;
                if (r2 < 1.0) deposit.add(c, static_cast<float>(sigma * std::exp(-kKernelFalloff * r2)), src);
            }
}

// A volume's voxels: the extinction at the centre where the voxel lies wholly inside, the mean of
// kSurfaceSamples³ (noise: kNoiseSurfaceSamples³) points where its surface crosses it. Both shapes are convex, so a voxel is
// wholly inside (or outside) when the ball around it is, in the shape's unit frame.
class VolumeSampler {
public:
    VolumeSampler(const Volume& v, double h) : v_(v), h_(h) {
        // The Frobenius norm of world → unit frame bounds its largest stretch.
        const glm::dmat3 toLocal(v.toLocal);
        double stretch2 = 0.0;
        for (int col = 0; col < 3; ++col) {
            const glm::dvec3 unit = 2.0 * toLocal[col] / v.size;
            stretch2 += glm::dot(unit, unit);
        }
        const double stretch = std::sqrt(stretch2);
        reach_ = 0.8660254037844386 * h * stretch;  // the voxel's circumscribed ball, in unit lengths (an upper bound)
    }

    double value(const glm::dvec3& centre) const {
        const glm::dvec3 u = glm::dvec3(v_.toLocal * glm::dvec4(centre, 1.0)) / (0.5 * v_.size);
        const double d = v_.shape == VolumeShape::Ellipsoid ? glm::length(u) : std::max({std::abs(u.x), std::abs(u.y), std::abs(u.z)});
        if (d - reach_ >= 1.0) return 0.0;
        if (d + reach_ <= 1.0) return v_.noise ? volumeExtinction(v_, centre) : v_.sigma();
        const int n = v_.noise ? kNoiseSurfaceSamples : kSurfaceSamples;
        double sum = 0.0;
        for (int k = 0; k < n * n * n; ++k) {
            const glm::dvec3 sub(k % n, (k / n) % n, k / (n * n));
            sum += volumeExtinction(v_, centre + h_ * ((sub + 0.5) / double(n) - 0.5));
        }
        return sum / (n * n * n);
    }

private:
    const Volume& v_;
    double h_;
    double reach_ = 0.0;
};

// The index box of the voxels that may meet the volume (a voxel reaches half a side past its centre).
std::pair<glm::ivec3, glm::ivec3> volumeIndexBox(const Volume& v, double h) {
    const Aabb b = volumeBounds(v);
    return {glm::ivec3(glm::ceil((b.min - 0.5 * h) / h)), glm::ivec3(glm::floor((b.max + 0.5 * h) / h))};
}

// Slices of a volume sampled at once, in parallel (a noise volume's surface voxels take 512
// evaluations each), then deposited in order: OpenVDB's accessors are not for concurrent writes.
// Up to 16 slices, and at most about 4M values (16 MB) at a time.
constexpr std::size_t kValuesAtOnce = std::size_t{1} << 22;

void fillVolume(const Volume& v, double h, Deposit& deposit, ProgressBar* progress) {
    const VolumeSampler sampler(v, h);
    const Source src = sourceOf(v.medium.albedo, v.medium.emission, v.medium.g, v.medium.phase);
    const std::pair<glm::ivec3, glm::ivec3> box = volumeIndexBox(v, h);
    const glm::ivec3 lo = box.first, hi = box.second;  // not a structured binding: clang 14 cannot capture one in a lambda
    const std::size_t nx = static_cast<std::size_t>(hi.x - lo.x + 1), ny = static_cast<std::size_t>(hi.y - lo.y + 1);
    const int slicesAtOnce = static_cast<int>(std::clamp<std::size_t>(kValuesAtOnce / (nx * ny), 1, 16));
    std::vector<float> values(nx * ny * static_cast<std::size_t>(slicesAtOnce));
    for (int z0 = lo.z; z0 <= hi.z; z0 += slicesAtOnce) {
        const int z1 = std::min(z0 + slicesAtOnce - 1, hi.z);
        auto at = [&](int x, int y, int z) -> float& {
            return values[(static_cast<std::size_t>(z - z0) * ny + static_cast<std::size_t>(y - lo.y)) * nx + static_cast<std::size_t>(x - lo.x)];
        };
        tbb::parallel_for(tbb::blocked_range<int>(z0, z1 + 1), [&](const tbb::blocked_range<int>& slices) {
            for (int z = slices.begin(); z != slices.end(); ++z)
                for (int y = lo.y; y <= hi.y; ++y)
                    for (int x = lo.x; x <= hi.x; ++x) at(x, y, z) = static_cast<float>(sampler.value(centreOf(openvdb::Coord(x, y, z), h)));
        });
        openvdb::Coord c;
        for (c.z() = z0; c.z() <= z1; ++c.z())
            for (c.y() = lo.y; c.y() <= hi.y; ++c.y())
                for (c.x() = lo.x; c.x() <= hi.x; ++c.x()) deposit.add(c, at(c.x(), c.y(), c.z()), src);
        if (progress) progress->advance(static_cast<std::size_t>(z1 - z0 + 1));
    }
}

// σ-weighted sums → means: each active voxel's sum over its density.
template <typename GridT>
void normalise(GridT& sums, const openvdb::FloatGrid& density) {
    const auto acc = density.getConstAccessor();
    for (auto it = sums.beginValueOn(); it; ++it) it.setValue(it.getValue() / acc.getValue(it.getCoord()));
}

template <typename GridT>
typename GridT::Ptr makeGrid(const std::string& name, const openvdb::math::Transform::Ptr& transform) {
    auto grid = GridT::create();
    grid->setName(name);
    grid->setTransform(transform);
    grid->setCreator("Nimbus (sandbox export)");
    return grid;
}

void describe(MediumGrids& grids, const Uniformity& u) {
    auto& d = *grids.density;
    d.setGridClass(openvdb::GRID_FOG_VOLUME);
    d.insertMeta("nimbus_quantity", openvdb::StringMetadata("extinction sigma_t in 1/m, sampled at voxel centres"));
    d.insertMeta("phase", openvdb::StringMetadata(u.phase()));
    if (!grids.albedo) d.insertMeta("albedo", openvdb::Vec3SMetadata(toVdb(u.first.albedo)));
    if (!grids.emission) d.insertMeta("emission", openvdb::Vec3SMetadata(toVdb(u.first.emission)));
    if (!grids.g) d.insertMeta("g", openvdb::FloatMetadata(u.first.g));
    for (openvdb::Vec3SGrid* colour : {grids.albedo.get(), grids.emission.get()})
        if (colour) colour->setVectorType(openvdb::VEC_INVARIANT);  // a colour: no transform rotates it
}

Uniformity uniformity(const ParticleSet& particles, const std::vector<Volume>& volumes) {
    Uniformity u;
    for (std::size_t i = 0; i < particles.size(); ++i)
        if (particles.sigma[i] > 0.0f) u.see(sourceOf(particles.albedo[i], particles.emission[i], particles.g[i], particles.phase[i]), particles.phase[i]);
    for (const Volume& v : volumes) u.see(sourceOf(v.medium.albedo, v.medium.emission, v.medium.g, v.medium.phase), v.medium.phase);
    return u;
}

}  // namespace

openvdb::GridPtrVec MediumGrids::grids() const {
    openvdb::GridPtrVec out{density};
    if (albedo) out.push_back(albedo);
    if (emission) out.push_back(emission);
    if (g) out.push_back(g);
    return out;
}

MediumGrids buildMediumGrids(const ParticleSet& particles, const std::vector<Volume>& volumes, const GridPlan& plan, bool progress) {
    if (!plan.fits) throw std::invalid_argument("buildMediumGrids: the plan does not fit its voxel limit (GridPlan::fits)");
    openvdb::initialize();
    const double h = plan.voxel;
    const auto transform = openvdb::math::Transform::createLinearTransform(h);  // index (i, j, k) ↦ world (i, j, k)·h: voxel centres
    const Uniformity u = uniformity(particles, volumes);
    MediumGrids grids;
    grids.density = makeGrid<openvdb::FloatGrid>("density", transform);
    if (!u.albedo) grids.albedo = makeGrid<openvdb::Vec3SGrid>("albedo", transform);
    if (!u.emission) grids.emission = makeGrid<openvdb::Vec3SGrid>("emission", transform);
    if (!u.g) grids.g = makeGrid<openvdb::FloatGrid>("g", transform);

    std::size_t work = particles.size();
    for (const Volume& v : volumes) {
        const auto [lo, hi] = volumeIndexBox(v, h);
        work += static_cast<std::size_t>(std::max(hi.z - lo.z + 1, 0));
    }
    std::unique_ptr<ProgressBar> bar = progress ? std::make_unique<ProgressBar>("export", work) : nullptr;
    {
        Deposit deposit(grids);
        for (std::size_t i = 0; i < particles.size(); ++i) {
            splatParticle(particles, i, h, deposit);
            if (bar) bar->advance();
        }
        for (const Volume& v : volumes) fillVolume(v, h, deposit, bar.get());
    }
    if (bar) bar->finish();

    if (grids.albedo) {
        normalise(*grids.albedo, *grids.density);
        // A mean of albedos in [0, 1] may round an ulp past 1 in float.
        for (auto it = grids.albedo->beginValueOn(); it; ++it) it.setValue(openvdb::math::minComponent(it.getValue(), openvdb::Vec3s(1.0f)));
    }
    if (grids.emission) normalise(*grids.emission, *grids.density);
    if (grids.g) normalise(*grids.g, *grids.density);
    for (const auto& grid : grids.grids()) grid->pruneGrid(0.0f);  // uniform leaves (a volume's inside) become tiles
    describe(grids, u);
    return grids;
}

void writeVdb(const std::filesystem::path& path, const MediumGrids& grids, const ExportInfo& info) {
    openvdb::initialize();
    const std::filesystem::path partial = path.string() + ".part";
    try {
        openvdb::MetaMap meta;
        meta.insertMeta("nimbus_scene", openvdb::StringMetadata(info.scene));
        meta.insertMeta("nimbus_time", openvdb::DoubleMetadata(info.time));
        openvdb::io::File file(partial.string());
        file.write(grids.grids(), meta);
        file.close();
        std::filesystem::rename(partial, path);
    } catch (const std::exception& e) {
        std::error_code ignored;
        std::filesystem::remove(partial, ignored);
        throwInputError(path.string(), "", "", std::string("cannot write the VDB file: ") + e.what());
    }
}

}  // namespace nimbus::media::vdb
