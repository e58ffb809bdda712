#pragma once
// The medium along one camera ray, in closed form: the particles it crosses, split into pieces at
// every chord endpoint (inside a piece the same particles are active, so everything is smooth), the
// exact optical depth of each piece, and clusters of overlapping chords. It answers "where along the
// ray has the optical depth since the cluster start reached s?" (Newton on the closed form), which
// is how the quadrature places its samples (reference_renderer.h, "Quadrature").
//
// Volumes (volume.h) join the particles as pieces: a constant one's optical depth is σ times the
// length; a noise volume's is tabulated along its chord by adaptive Simpson quadrature (nodes where
// the estimate settled to 1e-7 of the local depth) and read between nodes by the cubic Hermite
// interpolant of τ with slopes σ_t, which the nodes hold exactly. Everything below treats all alike.
//
// Does not: evaluate lighting; own the particles or volumes (indices into their lists).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/media/particle_bvh.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/volume.h"

namespace nimbus::media::reference {

// Along the ray a particle's extinction is σ_i ρ_i(t) = peak · exp(-(√k (t - tClosest))²), so its optical
// depth from t0 to t1 is scale · [erf(√k (t1 - tClosest)) - erf(√k (t0 - tClosest))].
struct RayParticle {
    std::uint32_t index = 0;  // into the ParticleSet, or the volume list where `volume`
    bool volume = false;      // constant extinction `sigma` over [enter, exit] (peak = σ, scale unused)
    double tClosest = 0.0, b2 = 0.0, halfChord = 0.0;
    double enter = 0.0, exit = 0.0;  // chord clipped to [0, end]
    double sigma = 0.0, radius = 0.0;
    double sqrtK = 0.0;              // √(4.5)/R
    double peak = 0.0;               // σ exp(-k b²): extinction at the closest point
    double scale = 0.0;              // peak · √π / (2√k)
    std::int32_t table = -1;         // a noise volume's depth table (ViewRayMedium), else −1
};

// A noise volume's optical depth along one ray: nodes t, τ from the chord's start, and σ_t there.
struct DepthTable {
    std::vector<double> t, tau, sigma;
    double at(double x) const;  // τ at x, cubic Hermite between nodes, clamped to the chord
};
// Tabulates `volume` (which has noise) on origin + t·dir over [a, b].
DepthTable tabulateOpticalDepth(const Volume& volume, const glm::dvec3& origin, const glm::dvec3& dir, double a, double b,
                                double tolerance = 1e-7);

struct RayCluster {
    std::uint32_t firstPiece = 0, endPiece = 0;  // pieces [first, end)
    double opticalDepthBefore = 0.0;             // τ from the eye to the cluster start
    double opticalDepth = 0.0;                   // τ across the cluster
};

// Where a sample landed: the ray parameter and the piece (for its active particles).
struct RaySample {
    double t = 0.0;
    std::uint32_t piece = 0;
};

class ViewRayMedium {
public:
    // Collects the particles on origin + t·dir, t in [0, end] (end may be +inf).
    void build(const ParticleBvh& bvh, const ParticleSet& particles, const glm::dvec3& origin, const glm::dvec3& dir,
               double end, const std::vector<Volume>& volumes = {});

    bool empty() const { return clusters_.empty(); }
    // τ(0, end): the direct sum of each particle's closed form over its whole (clipped) chord.
    double totalOpticalDepth() const { return totalOpticalDepth_; }
    const std::vector<RayCluster>& clusters() const { return clusters_; }
    const std::vector<RayParticle>& particles() const { return rayParticles_; }

    // The active particles of a piece (indices into particles()).
    const std::uint32_t* activeBegin(std::uint32_t piece) const { return active_.data() + activeStart_[piece]; }
    const std::uint32_t* activeEnd(std::uint32_t piece) const { return active_.data() + activeStart_[piece + 1]; }

    // The point of cluster c where the optical depth since the cluster start equals s (0 <= s <= τ_c).
    RaySample locate(std::uint32_t cluster, double s) const;

    // The inverse of locate: the optical depth from cluster c's start to ray parameter t (clamped to
    // the cluster), and the cluster's extent along the ray.
    double opticalDepthTo(std::uint32_t cluster, double t) const;
    double clusterStart(std::uint32_t cluster) const { return breaks_[clusters_[cluster].firstPiece]; }
    double clusterEnd(std::uint32_t cluster) const { return breaks_[clusters_[cluster].endPiece]; }

    // Σ σ_i ρ_i over a piece's active particles at ray parameter t, and each term into `terms`.
    double extinctionAt(std::uint32_t piece, double t, std::vector<double>* terms = nullptr) const;

private:
    void collect(const ParticleBvh& bvh, const ParticleSet& particles, const glm::dvec3& origin, const glm::dvec3& dir, double end);
    void collectVolumes(const std::vector<Volume>& volumes, const glm::dvec3& origin, const glm::dvec3& dir, double end);
    // A ray particle's optical depth over [a, b] inside one of its pieces, whose erf (a table's τ)
    // at the piece start is `erfStart`.
    double depthInPiece(const RayParticle& p, double pieceStart, double erfStart, double b) const;
    // The extinction of ray particle p at ray parameter t.
    double extinctionOf(const RayParticle& p, double t) const;
    void buildPieces();
    std::vector<double> pieceDepths();
    void buildClusters(const std::vector<double>& pieceDepth);

    std::vector<RayParticle> rayParticles_;
    std::vector<double> breaks_;            // piece k is [breaks_[k], breaks_[k+1]]
    std::vector<double> cumulative_;        // τ from the cluster start to breaks_[k] (per cluster)
    std::vector<std::uint32_t> activeStart_, active_;  // CSR: active particles of each piece
    std::vector<double> activeErfStart_;    // per CSR entry: erf(√k (piece start - tClosest))
    std::vector<RayCluster> clusters_;
    std::vector<std::uint32_t> candidates_;  // the BVH's particles, then each ray particle's first and end piece
    std::vector<DepthTable> tables_;         // the noise volumes' on this ray
    const std::vector<Volume>* volumes_ = nullptr;
    glm::dvec3 origin_{0.0}, dir_{0.0};
    double totalOpticalDepth_ = 0.0;
};

}  // namespace nimbus::media::reference
