#include "view_ray_medium.h"

#include <algorithm>
#include <cmath>

#include "nimbus/media/optics.h"

namespace nimbus::media::reference {

void ViewRayMedium::build(const ParticleBvh& bvh, const ParticleSet& particles, const glm::dvec3& origin,
                          const glm::dvec3& dir, double end, const std::vector<Volume>& volumes) {
    rayParticles_.clear();
    breaks_.clear();
    cumulative_.clear();
    activeStart_.clear();
    active_.clear();
    activeErfStart_.clear();
    clusters_.clear();
    candidates_.clear();
    tables_.clear();
    volumes_ = &volumes;
    origin_ = origin;
    dir_ = dir;
    totalOpticalDepth_ = 0.0;
    collect(bvh, particles, origin, dir, end);
    collectVolumes(volumes, origin, dir, end);
    if (rayParticles_.empty()) return;
    buildPieces();
    buildClusters(pieceDepths());
}

// The particles whose chords the ray crosses, in index order, and the exact total optical depth.
void ViewRayMedium::collect(const ParticleBvh& bvh, const ParticleSet& particles, const glm::dvec3& origin, const glm::dvec3& dir,
                            double end) {
    bvh.forEachOnSegment(origin, dir, 0.0, end, [&](std::uint32_t i) {
        candidates_.push_back(i);
        return true;
    });
    // Sorting by particle index makes the ray's particle list independent of the tree's traversal.
    std::sort(candidates_.begin(), candidates_.end());
    for (const std::uint32_t i : candidates_) {
        const double radius = particles.radius[i];
        const ChordGeometry chord = chordGeometry(origin, dir, particles.position[i], radius);
        if (!chord.hit()) continue;
        RayParticle p;
        p.index = i;
        p.tClosest = chord.tClosest;
        p.b2 = chord.b2;
        p.halfChord = chord.halfChord;
        p.enter = std::max(0.0, chord.tEnter());
        p.exit = std::min(end, chord.tExit());
        p.sigma = particles.sigma[i];
        p.radius = radius;
        if (!(p.exit > p.enter) || !(p.sigma > 0.0)) continue;
        p.sqrtK = std::sqrt(kKernelFalloff) / radius;
        p.peak = p.sigma * std::exp(-kKernelFalloff * p.b2 / (radius * radius));
        p.scale = p.peak * std::sqrt(kPi) / (2.0 * p.sqrtK);
        rayParticles_.push_back(p);
        // The exact closed form for the total (the transmittance the pixel reports).
        totalOpticalDepth_ += particleOpticalDepthOnChord(p.sigma, p.radius, p.b2, p.halfChord, p.enter - p.tClosest,
                                                          p.exit - p.tClosest);
    }
}

void ViewRayMedium::collectVolumes(const std::vector<Volume>& volumes, const glm::dvec3& origin, const glm::dvec3& dir, double end) {
    for (std::size_t v = 0; v < volumes.size(); ++v) {
        const VolumeChord chord = volumeChord(volumes[v], origin, dir);
        RayParticle p;
        p.index = static_cast<std::uint32_t>(v);
        p.volume = true;
        p.enter = std::max(0.0, chord.enter);
        p.exit = std::min(end, chord.exit);
        p.sigma = p.peak = volumes[v].sigma();
        if (!chord.hit() || !(p.exit > p.enter) || !(p.sigma > 0.0)) continue;
        if (volumes[v].noise) {
            tables_.push_back(tabulateOpticalDepth(volumes[v], origin, dir, p.enter, p.exit));
            p.table = static_cast<std::int32_t>(tables_.size() - 1);
            totalOpticalDepth_ += tables_.back().tau.back();
        } else {
            totalOpticalDepth_ += p.sigma * (p.exit - p.enter);
        }
        rayParticles_.push_back(p);
    }
}

double ViewRayMedium::depthInPiece(const RayParticle& p, double pieceStart, double erfStart, double b) const {
    if (p.table >= 0) return tables_[static_cast<std::size_t>(p.table)].at(b) - erfStart;
    if (p.volume) return p.sigma * (b - pieceStart);
    return p.scale * (std::erf(p.sqrtK * (b - p.tClosest)) - erfStart);
}

double ViewRayMedium::extinctionOf(const RayParticle& p, double t) const {
    if (p.table >= 0) return volumeExtinction((*volumes_)[p.index], origin_ + t * dir_);
    if (p.volume) return p.peak;
    const double x = p.sqrtK * (t - p.tClosest);
    return p.peak * std::exp(-x * x);
}

namespace {

// Adaptive Simpson on [a, b] (fa, fm, fb at a, its middle, b; `whole` Simpson's rule there),
// appending each accepted interval's middle and end as nodes of `table`.
template <typename F>
void refineTable(const F& sigma, double a, double b, double fa, double fm, double fb, double whole, double tolerance, int depth,
                 DepthTable& table) {
    const double m = 0.5 * (a + b);
    const double flm = sigma(0.5 * (a + m)), frm = sigma(0.5 * (m + b));
    const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm), right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    if (depth > 0 && std::abs(left + right - whole) > 15.0 * (tolerance * std::abs(left + right) + 1e-14)) {
        refineTable(sigma, a, m, fa, flm, fm, left, tolerance, depth - 1, table);
        refineTable(sigma, m, b, fm, frm, fb, right, tolerance, depth - 1, table);
        return;
    }
    const double before = table.tau.back();
    table.t.insert(table.t.end(), {m, b});
    table.tau.insert(table.tau.end(), {before + left, before + left + right});
    table.sigma.insert(table.sigma.end(), {fm, fb});
}

}  // namespace

DepthTable tabulateOpticalDepth(const Volume& volume, const glm::dvec3& origin, const glm::dvec3& dir, double a, double b, double tolerance) {
    DepthTable table;
    const auto sigma = [&](double t) { return volumeExtinction(volume, origin + t * dir); };
    table.t.push_back(a);
    table.tau.push_back(0.0);
    table.sigma.push_back(sigma(a));
    const int intervals = volumeQuadratureIntervals(volume, dir, b - a);
    const double h = (b - a) / intervals;
    for (int i = 0; i < intervals; ++i) {
        const double lo = a + i * h, hi = i + 1 == intervals ? b : lo + h, m = 0.5 * (lo + hi);
        const double fa = table.sigma.back(), fm = sigma(m), fb = sigma(hi);
        refineTable(sigma, lo, hi, fa, fm, fb, (hi - lo) / 6.0 * (fa + 4.0 * fm + fb), tolerance, 24, table);
    }
    return table;
}

double DepthTable::at(double x) const {
    if (!(x > t.front())) return 0.0;
    if (!(x < t.back())) return tau.back();
    const auto i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin()) - 1;
    const double h = t[i + 1] - t[i];
    if (!(h > 0.0)) return tau[i];
    const double s = (x - t[i]) / h, s2 = s * s, s3 = s2 * s;
    const double value = (2.0 * s3 - 3.0 * s2 + 1.0) * tau[i] + (s3 - 2.0 * s2 + s) * h * sigma[i] + (-2.0 * s3 + 3.0 * s2) * tau[i + 1] +
                         (s3 - s2) * h * sigma[i + 1];
    return std::clamp(value, tau[i], tau[i + 1]);
}

// Pieces between consecutive chord ends, and which particles are active in each (CSR). A particle
// covers pieces [index of enter, index of exit): both values are breakpoints, so the binary searches
// find them exactly. Leaves each ray particle's first and end piece in candidates_.
void ViewRayMedium::buildPieces() {
    for (const RayParticle& p : rayParticles_) {
        breaks_.push_back(p.enter);
        breaks_.push_back(p.exit);
    }
    std::sort(breaks_.begin(), breaks_.end());
    breaks_.erase(std::unique(breaks_.begin(), breaks_.end()), breaks_.end());
    const std::size_t pieces = breaks_.size() - 1;
    activeStart_.assign(pieces + 1, 0);
    std::vector<std::uint32_t>& span = candidates_;  // reused as scratch: first and end piece per ray particle
    span.resize(2 * rayParticles_.size());
    for (std::size_t r = 0; r < rayParticles_.size(); ++r) {
        const auto a = static_cast<std::uint32_t>(std::lower_bound(breaks_.begin(), breaks_.end(), rayParticles_[r].enter) - breaks_.begin());
        const auto b = static_cast<std::uint32_t>(std::lower_bound(breaks_.begin(), breaks_.end(), rayParticles_[r].exit) - breaks_.begin());
        span[2 * r] = a;
        span[2 * r + 1] = b;
        for (std::uint32_t k = a; k < b; ++k) ++activeStart_[k + 1];
    }
    for (std::size_t k = 0; k < pieces; ++k) activeStart_[k + 1] += activeStart_[k];
    active_.resize(activeStart_[pieces]);
    activeErfStart_.resize(activeStart_[pieces]);
}

// Piece optical depths as differences of erf at consecutive breaks: one erf per (particle, break).
// A difference loses relative precision on tiny pieces but keeps ~1e-16 · τ absolute, which is
// all the cumulative depth (the sample map) needs; the pixel's T(0,d) uses the closed form.
std::vector<double> ViewRayMedium::pieceDepths() {
    const std::size_t pieces = breaks_.size() - 1;
    const std::vector<std::uint32_t>& span = candidates_;
    std::vector<double> pieceDepth(pieces, 0.0);
    std::vector<std::uint32_t> fill(activeStart_.begin(), activeStart_.end() - 1);
    for (std::size_t r = 0; r < rayParticles_.size(); ++r) {
        const RayParticle& p = rayParticles_[r];
        if (p.table >= 0) {  // tabulated: differences of the table's τ
            const DepthTable& table = tables_[static_cast<std::size_t>(p.table)];
            double previous = table.at(breaks_[span[2 * r]]);
            for (std::uint32_t k = span[2 * r]; k < span[2 * r + 1]; ++k) {
                const double next = table.at(breaks_[k + 1]);
                activeErfStart_[fill[k]] = previous;
                active_[fill[k]++] = static_cast<std::uint32_t>(r);
                pieceDepth[k] += next - previous;
                previous = next;
            }
            continue;
        }
        if (p.volume) {  // constant: σ times each piece's length
            for (std::uint32_t k = span[2 * r]; k < span[2 * r + 1]; ++k) {
                activeErfStart_[fill[k]] = 0.0;
                active_[fill[k]++] = static_cast<std::uint32_t>(r);
                pieceDepth[k] += p.sigma * (breaks_[k + 1] - breaks_[k]);
            }
            continue;
        }
        double previous = std::erf(p.sqrtK * (breaks_[span[2 * r]] - p.tClosest));
        for (std::uint32_t k = span[2 * r]; k < span[2 * r + 1]; ++k) {
            const double next = std::erf(p.sqrtK * (breaks_[k + 1] - p.tClosest));
            activeErfStart_[fill[k]] = previous;
            active_[fill[k]++] = static_cast<std::uint32_t>(r);
            pieceDepth[k] += p.scale * (next - previous);
            previous = next;
        }
    }
    return pieceDepth;
}

// Clusters: maximal runs of pieces with active particles; cumulative depth restarts in each.
void ViewRayMedium::buildClusters(const std::vector<double>& pieceDepth) {
    const std::size_t pieces = pieceDepth.size();
    cumulative_.assign(breaks_.size(), 0.0);
    double before = 0.0;
    for (std::uint32_t k = 0; k < pieces; ++k) {
        if (activeStart_[k] == activeStart_[k + 1]) continue;  // a gap between particles
        if (clusters_.empty() || clusters_.back().endPiece != k) {
            if (!clusters_.empty()) before += clusters_.back().opticalDepth;
            clusters_.push_back({k, k, before, 0.0});
            cumulative_[k] = 0.0;
        }
        RayCluster& c = clusters_.back();
        c.opticalDepth += std::max(0.0, pieceDepth[k]);
        cumulative_[k + 1] = c.opticalDepth;
        c.endPiece = k + 1;
    }
}

double ViewRayMedium::extinctionAt(std::uint32_t piece, double t, std::vector<double>* terms) const {
    if (terms) terms->clear();
    double sum = 0.0;
    for (const std::uint32_t* a = activeBegin(piece); a != activeEnd(piece); ++a) {
        const double term = extinctionOf(rayParticles_[*a], t);
        sum += term;
        if (terms) terms->push_back(term);
    }
    return sum;
}

double ViewRayMedium::opticalDepthTo(std::uint32_t cluster, double t) const {
    const RayCluster& c = clusters_[cluster];
    if (!(t > breaks_[c.firstPiece])) return 0.0;
    if (t >= breaks_[c.endPiece]) return c.opticalDepth;
    const auto k = static_cast<std::uint32_t>(
        std::upper_bound(breaks_.begin() + c.firstPiece, breaks_.begin() + c.endPiece, t) - breaks_.begin()) - 1;
    double s = cumulative_[k];
    const double* erfStart = activeErfStart_.data() + activeStart_[k];
    for (const std::uint32_t* a = activeBegin(k); a != activeEnd(k); ++a)
        s += depthInPiece(rayParticles_[*a], breaks_[k], erfStart[a - activeBegin(k)], t);
    return std::clamp(s, cumulative_[k], cumulative_[k + 1]);
}

RaySample ViewRayMedium::locate(std::uint32_t cluster, double s) const {
    const RayCluster& c = clusters_[cluster];
    s = std::clamp(s, 0.0, c.opticalDepth);
    // The piece whose cumulative range holds s (skipping pieces of zero optical depth).
    const auto first = cumulative_.begin() + c.firstPiece + 1;
    const auto last = cumulative_.begin() + c.endPiece;  // cumulative_[endPiece] is the cluster total
    std::uint32_t k = static_cast<std::uint32_t>(std::lower_bound(first, last, s) - cumulative_.begin()) - 1;
    k = std::min(k, c.endPiece - 1);

    const double lo0 = breaks_[k], hi0 = breaks_[k + 1];
    const double target = s - cumulative_[k];
    const double pieceDepth = cumulative_[k + 1] - cumulative_[k];
    if (!(pieceDepth > 0.0) || target <= 0.0) return {lo0, k};
    if (target >= pieceDepth) return {hi0, k};

    // Safeguarded Newton on f(t) = τ(piece start, t) - target: increasing, f' = σ_t(t) > 0 inside.
    // The sample only has to land where the map says to ~1e-10 of the piece: the quadrature's
    // change of variables is exact whatever the sample positions, they only choose where S̄ is read.
    const std::uint32_t* begin = activeBegin(k);
    const std::uint32_t* end = activeEnd(k);
    const double* erfStart = activeErfStart_.data() + activeStart_[k];
    double lo = lo0, hi = hi0;
    double t = lo0 + (hi0 - lo0) * (target / pieceDepth);
    const double tTolerance = 1e-10 * (hi0 - lo0) + 1e-15 * std::abs(hi0);
    for (int iteration = 0; iteration < 100; ++iteration) {
        double f = -target, slope = 0.0;
        for (const std::uint32_t* a = begin; a != end; ++a) {
            const RayParticle& p = rayParticles_[*a];
            f += depthInPiece(p, lo0, erfStart[a - begin], t);
            slope += extinctionOf(p, t);
        }
        if (f == 0.0) break;
        if (f < 0.0) lo = t; else hi = t;
        double next = slope > 0.0 ? t - f / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const double step = std::abs(next - t);
        t = next;
        if (step <= tTolerance || hi - lo <= tTolerance) break;
    }
    return {t, k};
}

}  // namespace nimbus::media::reference
