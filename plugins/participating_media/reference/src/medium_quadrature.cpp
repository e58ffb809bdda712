#include "medium_quadrature.h"

#include <algorithm>
#include <cmath>

#include "nimbus/media/optics.h"

namespace nimbus::media::reference {
namespace {

// QUADPACK's 15-point Kronrod rule and its embedded 7-point Gauss rule on [-1, 1] (nodes ±x).
constexpr double kKronrodNodes[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                     0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                     0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                     0.207784955007898467600689403773245, 0.0};
constexpr double kKronrodWeights[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                       0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                       0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                       0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// Gauss weights for kKronrodNodes[1], [3], [5] (±) and [7] (the centre).
constexpr double kGaussWeights[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                     0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

double maxAbs(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

}  // namespace

void MediumQuadrature::evaluate(const ViewRayMedium& medium, const SourceFunction& source, Interval& iv) {
    const double mid = 0.5 * (iv.v0 + iv.v1), half = 0.5 * (iv.v1 - iv.v0);
    auto at = [&](double v) {
        // v = 1 - exp(-s)  ⇔  s = -log(1 - v): the optical depth since the cluster start.
        const double s = -std::log1p(-std::min(v, 1.0));
        return source(medium.locate(iv.cluster, s));
    };
    glm::dvec3 kronrod(0.0), gauss(0.0);
    for (int k = 0; k < 7; ++k) {
        const glm::dvec3 f = at(mid - half * kKronrodNodes[k]) + at(mid + half * kKronrodNodes[k]);
        kronrod += kKronrodWeights[k] * f;
        if (k % 2 == 1) gauss += kGaussWeights[k / 2] * f;
    }
    const glm::dvec3 centre = at(mid);
    kronrod += kKronrodWeights[7] * centre;
    gauss += kGaussWeights[3] * centre;
    evaluations_ += 15;
    iv.value = iv.weight * half * kronrod;
    iv.error = iv.weight * half * maxAbs(kronrod - gauss);
}

QuadratureResult MediumQuadrature::integrate(const ViewRayMedium& medium, const SourceFunction& source,
                                             const glm::dvec3& offset, const QuadratureSettings& settings,
                                             std::span<const double> cuts) {
    intervals_.clear();
    evaluations_ = 0;
    const auto& clusters = medium.clusters();
    for (std::uint32_t c = 0; c < clusters.size(); ++c) {
        Interval iv;
        iv.cluster = c;
        iv.v1 = opacity(clusters[c].opticalDepth);
        iv.weight = transmittance(clusters[c].opticalDepthBefore);
        if (!(iv.v1 > 0.0) || !(iv.weight > 0.0)) continue;  // nothing there, or nothing of it reaches the eye
        // Start from up to three intervals: cut at half the cluster's opacity and at its middle along
        // the ray. The second cut matters where the cluster thins out: v packs a long, sparse tail into a
        // sliver, and a lone 15-point rule can step over the light changing there without noticing.
        // The caller's cuts matter near point and spot lights: a ray passing b from one carries a
        // spike ~b wide and I/b² high there, which no node of a wider first interval would find.
        const double t0 = medium.clusterStart(c), t1 = medium.clusterEnd(c);
        cuts_.assign({0.0, 0.5 * iv.v1, opacity(medium.opticalDepthTo(c, 0.5 * (t0 + t1))), iv.v1});
        for (double t : cuts)
            if (t > t0 && t < t1) cuts_.push_back(opacity(medium.opticalDepthTo(c, t)));
        std::sort(cuts_.begin(), cuts_.end());
        for (std::size_t q = 0; q + 1 < cuts_.size(); ++q) {
            if (!(cuts_[q + 1] > cuts_[q])) continue;
            Interval part = iv;
            part.v0 = cuts_[q];
            part.v1 = cuts_[q + 1];
            evaluate(medium, source, part);
            intervals_.push_back(part);
        }
    }

    // The floor scales with what the medium on this ray can send at most: its opacity times the
    // scene's radiance, so faint media are still refined (docs/design-notes.md).
    double rayOpacity = 0.0;
    if (!clusters.empty()) rayOpacity = opacity(clusters.back().opticalDepthBefore + clusters.back().opticalDepth);
    const double floor = settings.absoluteFloor * std::min(rayOpacity, 1.0);
    QuadratureResult result;
    for (;;) {
        // Sums in storage order: the same bits for the same ray, always.
        glm::dvec3 value(0.0);
        double error = 0.0;
        for (const Interval& iv : intervals_) {
            value += iv.value;
            error += iv.error;
        }
        result.value = value;
        result.errorEstimate = error;
        const double allowed = std::max(settings.tolerance * maxAbs(value + offset), floor);
        if (error <= allowed) break;

        std::size_t worst = intervals_.size();
        for (std::size_t j = 0; j < intervals_.size(); ++j)
            if (intervals_[j].depth < settings.maxDepth && intervals_[j].error > 0.0 &&
                (worst == intervals_.size() || intervals_[j].error > intervals_[worst].error))
                worst = j;
        if (worst == intervals_.size()) {
            result.converged = false;  // every interval that still has error is at the depth bound
            break;
        }
        Interval left = intervals_[worst], right = intervals_[worst];
        const double mid = 0.5 * (left.v0 + left.v1);
        left.v1 = mid;
        right.v0 = mid;
        left.depth = right.depth = intervals_[worst].depth + 1;
        evaluate(medium, source, left);
        evaluate(medium, source, right);
        intervals_[worst] = left;
        intervals_.push_back(right);
    }
    result.evaluations = evaluations_;
    return result;
}

}  // namespace nimbus::media::reference
