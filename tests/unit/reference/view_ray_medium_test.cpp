// Tests plugins/participating_media/reference/src/view_ray_medium.cpp: the closed-form decomposition
// of a view ray and the sample map (locate) against brute force.
#include "view_ray_medium.h"

#include <gtest/gtest.h>

#include "reference_fixture.h"

namespace nimbus::media::test {
namespace {

using reference::ViewRayMedium;

// Σ_i τ_i over [t0, t1], every particle by its own closed form (no pieces, no caches).
double directDepth(const ParticleSet& set, const glm::dvec3& o, const glm::dvec3& d, double t0, double t1) {
    double tau = 0.0;
    for (std::size_t i = 0; i < set.size(); ++i)
        tau += particleOpticalDepth(chordGeometry(o, d, set.position[i], set.radius[i]), set.sigma[i], set.radius[i], t0, t1);
    return tau;
}

TEST(ViewRayMedium, ClustersPiecesAndTheSampleMapAreConsistentWithTheClosedForm) {
    ParticleSet set;
    addRandomCloud(set, 300, 17, {-6, -2, -6}, {6, 2, 6}, 0.2f, 1.5f, 2.0f, medium(0.8f));
    const ParticleBvh bvh(set);
    ViewRayMedium m;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int clusters = 0, samples = 0;
    double worstMap = 0.0;
    for (int r = 0; r < 60; ++r) {
        const glm::dvec3 o(12.0 * u(rng), 3.0 * u(rng), 12.0);
        const glm::dvec3 d = glm::normalize(glm::dvec3(0.3 * u(rng), 0.1 * u(rng), -1.0));
        const double end = r % 3 == 0 ? 14.0 : 1e30;  // some rays stop inside the cloud (a mesh hit)
        m.build(bvh, set, o, d, end);
        const double total = directDepth(set, o, d, 0.0, end);
        EXPECT_NEAR(m.totalOpticalDepth(), total, 1e-12 * (1.0 + total));
        double sum = 0.0;
        for (std::uint32_t c = 0; c < m.clusters().size(); ++c) {
            const auto& cluster = m.clusters()[c];
            ++clusters;
            EXPECT_NEAR(cluster.opticalDepthBefore, sum, 1e-11 * (1.0 + sum));
            EXPECT_NEAR(cluster.opticalDepthBefore, directDepth(set, o, d, 0.0, m.clusterStart(c)), 1e-11 * (1.0 + sum));
            EXPECT_NEAR(cluster.opticalDepth, directDepth(set, o, d, m.clusterStart(c), m.clusterEnd(c)),
                        1e-11 * (1.0 + cluster.opticalDepth));
            sum += cluster.opticalDepth;
            for (int k = 0; k <= 20; ++k) {
                const double s = cluster.opticalDepth * k / 20.0;
                const reference::RaySample sample = m.locate(c, s);
                ++samples;
                ASSERT_GE(sample.t, m.clusterStart(c));
                ASSERT_LE(sample.t, m.clusterEnd(c));
                const double reached = directDepth(set, o, d, m.clusterStart(c), sample.t);
                const double e = std::abs(reached - s) / (1e-12 + cluster.opticalDepth);
                worstMap = std::max(worstMap, e);
                EXPECT_LT(e, 1e-9);
                EXPECT_NEAR(m.opticalDepthTo(c, sample.t), s, 1e-9 * (1.0 + cluster.opticalDepth));
                // σ_t at the sample from the piece's active list equals the sum over all particles
                // (inside the cluster: at its ends the boundary particle is in or out by convention).
                if (k > 0 && k < 20) {
                    EXPECT_NEAR(m.extinctionAt(sample.piece, sample.t),
                            static_cast<double>(extinction(set, o + sample.t * d)),
                            1e-12 * (1.0 + m.extinctionAt(sample.piece, sample.t)));
                }
            }
        }
        EXPECT_NEAR(sum, total, 1e-11 * (1.0 + total));
    }
    std::printf("view ray: %d clusters, %d samples; sample map within %.3g of the cluster depth\n", clusters, samples, worstMap);
    EXPECT_GT(clusters, 60);
}

TEST(ViewRayMedium, EmptyRaysAndGaps) {
    ParticleSet set;
    const Medium m0 = medium(1.0f);
    set.push({0, 0, -5}, 1.0f, 1.0f, m0);
    set.push({0, 0, -10}, 1.0f, 1.0f, m0);  // a gap of 3 m between the two chords
    const ParticleBvh bvh(set);
    ViewRayMedium m;
    m.build(bvh, set, {0, 0, 0}, {0, 0, -1}, 1e30);
    ASSERT_EQ(m.clusters().size(), 2u);
    EXPECT_DOUBLE_EQ(m.clusterStart(0), 4.0);
    EXPECT_DOUBLE_EQ(m.clusterEnd(1), 11.0);
    m.build(bvh, set, {0, 0, 0}, {0, 0, -1}, 5.0);  // stops at the first centre
    ASSERT_EQ(m.clusters().size(), 1u);
    EXPECT_NEAR(m.totalOpticalDepth(), 0.5 * particleOpticalDepth(1.0, 1.0, 0.0, -1.0, 1.0), 1e-15);
    m.build(bvh, set, {5, 0, 0}, {0, 0, -1}, 1e30);
    EXPECT_TRUE(m.empty());
    EXPECT_EQ(m.totalOpticalDepth(), 0.0);
}

}  // namespace
}  // namespace nimbus::media::test
