#pragma once
// The in-scattering integral along one view ray, by globally adaptive Gauss–Kronrod (7/15) in the
// per-cluster variable v = 1 - exp(-τ) (reference_renderer.h, "Quadrature"):
//   ∫ T(0,t) σ_t(t) S̄(t) dt = Σ_clusters T(cluster start) ∫₀^{1-exp(-τ_c)} S̄(t(v)) dv.
// Each cluster starts as up to three intervals (cut at half its opacity and at its middle along the
// ray), further cut at the distances the caller names (where the source can spike: a point or spot
// light's closest approach); then the interval with the largest |K15 - G7| is bisected until the sum
// of those estimates is within the tolerance of the pixel value.
//
// Does not: know what the source is (a callback evaluates S̄ at a located sample).
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "view_ray_medium.h"

namespace nimbus::media::reference {

struct QuadratureSettings {
    double tolerance = 1e-4;     // relative, against the pixel value (max over RGB)
    double absoluteFloor = 0.0;  // radiance below which refining stops, for a ray of opacity 1 (scaled by the ray's)
    int maxDepth = 48;           // bisections of one interval
};

struct QuadratureResult {
    glm::dvec3 value{0.0};
    double errorEstimate = 0.0;  // Σ |K15 - G7| (max over RGB), weighted
    int evaluations = 0;
    bool converged = true;
};

using SourceFunction = std::function<glm::dvec3(const RaySample&)>;

class MediumQuadrature {
public:
    // `offset` is the rest of the pixel (T(0,d)·L_s), which counts towards the relative tolerance.
    // `cuts` are distances along the ray where the first intervals must end (any order, any range).
    QuadratureResult integrate(const ViewRayMedium& medium, const SourceFunction& source, const glm::dvec3& offset,
                               const QuadratureSettings& settings, std::span<const double> cuts = {});

private:
    struct Interval {
        std::uint32_t cluster = 0;
        double v0 = 0.0, v1 = 0.0;
        double weight = 0.0;  // T at the cluster start
        glm::dvec3 value{0.0};
        double error = 0.0;
        int depth = 0;
    };
    void evaluate(const ViewRayMedium& medium, const SourceFunction& source, Interval& interval);

    std::vector<Interval> intervals_;
    std::vector<double> cuts_;
    int evaluations_ = 0;
};

}  // namespace nimbus::media::reference
