// Hard cases of the optics (issue "Speed against error ... and the hard cases"): optical depths far
// from 1, light along, against and across the view, a spot light inside the medium, and phase
// asymmetry g = ±0.99. Each case is a scene in tests/data/stability_scenes (written by
// generate_stability_scenes.py) and says what could go wrong and which code prevents it.
//
// Every case asserts (stability_harness.h): no NaN/Inf pixel in the reference or in either mode, no
// GL error, the reference converged (halving its tolerance changes it by < 1e-3 rel-RMSE), two
// frames of the same state identical, and each mode's rel-RMSE against the reference within the
// stated bound (15% unless the comment argues otherwise; RMS-relative error where the reference is
// sparse, stability_harness.h boundedError). Measured values: 160×90, llvmpipe.
#include <gtest/gtest.h>

#include "stability_harness.h"

namespace nimbus::stability {
namespace {


// ── Optical depth ~1e4: transmittance underflow ──────────────────────────────────────────────
// A cloud whose densest column has τ ≈ 1e4 (σ ≈ 5e3 /m), over a ground, in the sun.
// What could go wrong: e^−τ underflows to 0, so anything that divides by a transmittance, takes
// its log, or normalises by it gives Inf/NaN; 1 − e^−τ must be exactly 1, not 1 + rounding; a
// shading point placed by inverting the kernel's cumulative depth (erfinv at ±1) is −inf; block
// sums weighted by τ (τ·t, τ·albedo) could overflow; light slices holding τ ~ 1e4 must still
// interpolate to a finite e^−τ.
// What prevents it:
//   reference: optics.h transmittance() (0 for huge τ, never NaN) and opacity() (−expm1);
//     light_transport.cpp LightTransport::transmittanceToLight (τ ≥ 64 counts as opaque); the
//     quadrature works in v = 1 − e^−τ (medium_quadrature.cpp MediumQuadrature::integrate), so
//     an opaque cluster is a finite interval of v and nothing behind it is evaluated.
//   real time: shaders/common/math.glsl oneMinusExpNeg; shaders/media/common/optics.glsl
//     chordShadingPoint (fraction → 1/τ, never 0/0) and erfInverse (argument clamped to
//     ±0.9999999, no log(0)); lighting.glsl scatteredLight (exp(−τ) of the slice value, 0 not
//     NaN); block_composite.frag divides the sums by τ only where τ > 0.
// Bound: 15%. Measured: particles 2.9%, blocks 4.1%.
const HardCase kOpticalDepth1e4{.name = "optical_depth_1e4", .scene = "optical_depth_1e4.gltf"};

TEST_F(StabilityTest, OpticalDepth1e4StaysFinite) { expectFiniteAndClean(kOpticalDepth1e4, runCase(context(), kOpticalDepth1e4)); }
TEST_F(StabilityTest, OpticalDepth1e4WithinBound) {
    const CaseRun& run = runCase(context(), kOpticalDepth1e4);
    expectWithinBound(kOpticalDepth1e4, run, MediaMode::Particles, kDefaultErrorBound);
    expectWithinBound(kOpticalDepth1e4, run, MediaMode::Blocks, kDefaultErrorBound);
}

// ── Optical depth ~1e-5: cancellation ────────────────────────────────────────────────────────
// The same kind of cloud with the densest column at τ ≈ 1e-5, on a black background with no
// ambient and no mesh: the medium's in-scattering is the whole image, so a relative error of the
// medium is the image's relative error.
// What could go wrong: 1 − e^−τ computed as 1 − exp(−τ) in float keeps ~1e-7 absolute, i.e. 1%
// of τ = 1e-5 and all of τ < 1e-7 (the thin rim of every particle); erf(b) − erf(a) of a short
// chord cancels; the reference's quadrature floor could stop it before it resolves so faint a
// medium.
// What prevents it: optics.h opacity() uses expm1; optics.cpp gaussianIntegralWidth integrates
// short intervals by Gauss–Legendre instead of subtracting erfs; shaders/common/math.glsl
// oneMinusExpNeg switches to its Taylor series below 1e-3; the reference floor is relative to the
// scene's radiance scale (reference_renderer.h), and its self-change is asserted.
// Bound: 15%. Measured: particles 0.0002%, blocks 2.1% — blocks mode's error here is its impostor
// resolution (impostor_scale 0.5 blurs silhouettes over ~2 px: 14% at 96×54, 0.85% there with
// impostor_scale 2), not cancellation; it shows only because nothing but the medium is in the image.
const HardCase kOpticalDepth1e5{.name = "optical_depth_1e-5", .scene = "optical_depth_1e-5.gltf"};

TEST_F(StabilityTest, OpticalDepth1eMinus5StaysFinite) { expectFiniteAndClean(kOpticalDepth1e5, runCase(context(), kOpticalDepth1e5)); }
TEST_F(StabilityTest, OpticalDepth1eMinus5WithinBound) {
    const CaseRun& run = runCase(context(), kOpticalDepth1e5);
    expectWithinBound(kOpticalDepth1e5, run, MediaMode::Particles, kDefaultErrorBound);
    expectWithinBound(kOpticalDepth1e5, run, MediaMode::Blocks, kDefaultErrorBound);
}

// ── Light parallel, antiparallel and perpendicular to the view ───────────────────────────────
// The sun shines straight down (−Y). Camera "parallel" looks straight down (the light comes from
// behind the eye), "antiparallel" straight up into the sun (everything seen is lit through the
// cloud), "perpendicular" horizontally. g = 0.6.
// What could go wrong: a light view built with the world up (0, 1, 0) as its up hint is
// degenerate for a light along ±Y (cross product 0 → NaN matrices, every slice lookup NaN); a
// camera looking along ±Y is degenerate for the same reason; billboards oriented with a helper
// axis parallel to the eye axis collapse; cos θ = ±1 exactly puts the Henyey–Greenstein
// denominator at its minimum (1 − |g|)².
// What prevents it: engine/gpu/src/light_views.cpp lookAlong (replaces an up hint within
// 0.99 of the axis); cameras come from the node's rotation, not a look-at (assets
// resolveCamera); shaders/media/particles/particles.vert picks the billboard helper axis by |axis.y|;
// shaders/media/common/optics.glsl henyeyGreenstein forms its denominator from |a ∓ b|², not a float cos θ.
// Bound: 15% each. Measured: parallel particles 0.09%, blocks 0.24%; antiparallel particles 4.6%,
// blocks 3.3%; perpendicular particles 0.96%, blocks 0.91%. Antiparallel particles were 1.5% while
// each particle took the light's transmittance at one point: the other particles' mass along the
// ray bends τl, which lighting.glsl layerLightTransmittance's one line in v does not follow (three
// samples, piecewise linear, gave 3.6% here but worse everywhere else). Blocks were 10.6% before
// their shading pieces were weighted by the depth profile's mass.
const HardCase kLightParallel{.name = "light_parallel", .scene = "light_directions.gltf", .camera = "parallel"};
const HardCase kLightAntiparallel{.name = "light_antiparallel", .scene = "light_directions.gltf", .camera = "antiparallel"};
const HardCase kLightPerpendicular{.name = "light_perpendicular", .scene = "light_directions.gltf", .camera = "perpendicular"};

TEST_F(StabilityTest, LightParallelToViewStaysFinite) { expectFiniteAndClean(kLightParallel, runCase(context(), kLightParallel)); }
TEST_F(StabilityTest, LightParallelToViewWithinBound) {
    const CaseRun& run = runCase(context(), kLightParallel);
    expectWithinBound(kLightParallel, run, MediaMode::Particles, kDefaultErrorBound);
    expectWithinBound(kLightParallel, run, MediaMode::Blocks, kDefaultErrorBound);
}
TEST_F(StabilityTest, LightAntiparallelToViewStaysFinite) {
    expectFiniteAndClean(kLightAntiparallel, runCase(context(), kLightAntiparallel));
}
// Blocks: looking into the light, every pixel is lit through the cloud, so the block light slices
// (each block's optical depth spread along the light ray as one Gaussian, block_slices.frag) decide
// the image; the error falls with more, smaller blocks: blocks=4 31%, 9 16.3%, 16 12.7%, 18 (the
// automatic round(2√80)) 13.1%, 40 6.7%, 80 4.2%.
TEST_F(StabilityTest, LightAntiparallelToViewWithinBound) {
    const CaseRun& run = runCase(context(), kLightAntiparallel);
    expectWithinBound(kLightAntiparallel, run, MediaMode::Particles, kDefaultErrorBound);
    expectWithinBound(kLightAntiparallel, run, MediaMode::Blocks, kDefaultErrorBound);
}
TEST_F(StabilityTest, LightPerpendicularToViewStaysFinite) {
    expectFiniteAndClean(kLightPerpendicular, runCase(context(), kLightPerpendicular));
}
TEST_F(StabilityTest, LightPerpendicularToViewWithinBound) {
    const CaseRun& run = runCase(context(), kLightPerpendicular);
    expectWithinBound(kLightPerpendicular, run, MediaMode::Particles, kDefaultErrorBound);
    expectWithinBound(kLightPerpendicular, run, MediaMode::Blocks, kDefaultErrorBound);
}

// ── A spot light inside the cloud ────────────────────────────────────────────────────────────
// A spot light at the middle of a cloud (σ 0.8 /m, particles R 0.5–1 m around it), shining down
// and sideways onto the ground; the camera sees the light's position.
// What could go wrong: E = I/d² is singular at the light, and camera rays pass within
// centimetres of it (the exact in-scattering there is finite only because ∫ du/(b² + u²) = π/b);
// light views are perspective from inside particle spheres (a tangent-cone billboard needs
// sqrt(d² − R²) < 0); the light's own position is inside particles, so "the part of the particle
// in front of the light" has to be clipped; at d = 0 the direction to the light is undefined.
// What prevents it: shaders/media/slices/light_slices.vert covers the whole view when the light is inside
// or at a sphere; light_slices.frag starts perspective light rays at the light
// (start = max(−h, −t_closest)); shaders/media/common/local_light_segment.glsl integrates the light along
// each particle's segment with u = u_l + b·tan φ (b ≥ 1e-4 R) instead of sampling the spike;
// shaders/common/lights.glsl sampleLight and assets light_model.cpp sampleLight return zero
// irradiance within 1e-9 m of the light; light_views.cpp perspectiveView keeps znear > 0.
// The reference's value near the light was checked independently (a 40000-point integral in the
// tan-substitution of one pixel's ray: 2.021 + 0.016 ambient against the reference's 2.037); where
// rays pass within millimetres of the light the reference itself fails (reference_near_light_test).
// Bound: 15%. Measured: particles 3.6% (9.0% with the light averaged over the kernel and applied
// at one point per particle; 178% before 213e2c7 put the cone inside that average), blocks 1.8%
// (2.5% before the lamp inside it doubled the blocks, block_partition.h; 3.2% before their shading pieces were weighted by mass; 110% while a block was lit at one point: the peak pixel (46, 21) at 96×54 read 0.016 against
// 2.04; block_lighting.glsl blockLocalLightSegment integrates the lamp over each block's segment
// with the block's own particles listed around the lamp, within the largest block's radius).
const HardCase kSpotInCloud{.name = "spot_in_cloud", .scene = "spot_in_cloud.gltf"};

TEST_F(StabilityTest, SpotLightInsideCloudStaysFinite) { expectFiniteAndClean(kSpotInCloud, runCase(context(), kSpotInCloud)); }
TEST_F(StabilityTest, SpotLightInsideCloudParticlesWithinBound) {
    expectWithinBound(kSpotInCloud, runCase(context(), kSpotInCloud), MediaMode::Particles, kDefaultErrorBound);
}
TEST_F(StabilityTest, SpotLightInsideCloudBlocksWithinBound) {
    expectWithinBound(kSpotInCloud, runCase(context(), kSpotInCloud), MediaMode::Blocks, kDefaultErrorBound);
}

// ── A spot light among opaque particles ──────────────────────────────────────────────────────
// Forty particles of 60–120 m, each of optical depth ~1e4, around a spot light; g = 0.99 (unseen
// variant 2 of seed 8, kept here).
// What could go wrong: near a lamp inside the medium, each layer's light is re-attenuated exactly
// by its listed neighbours: e^(their mass behind the point) undoes what the blend will take away.
// For τ = 1e4 that factor is inf, and the blend's transmittance of 0 turned it into NaN pixels
// (117 in particles, 29 in blocks at 160×90).
// What prevents it: shaders/media/common/lamp_neighbourhood.glsl caps the factor's log at 50 (a layer
// behind more than e^−50 of transmittance has nothing a float can give back).
// Bound: 15%. Measured: particles 5e-6, blocks 5e-6 (4.6% when this case was written).
const HardCase kSpotInOpaqueCloud{.name = "spot_in_opaque_cloud", .scene = "spot_in_opaque_cloud.gltf"};

TEST_F(StabilityTest, SpotLightAmongOpaqueParticlesStaysFinite) {
    expectFiniteAndClean(kSpotInOpaqueCloud, runCase(context(), kSpotInOpaqueCloud));
}
TEST_F(StabilityTest, SpotLightAmongOpaqueParticlesParticlesWithinBound) {
    expectWithinBound(kSpotInOpaqueCloud, runCase(context(), kSpotInOpaqueCloud), MediaMode::Particles, kDefaultErrorBound);
}
TEST_F(StabilityTest, SpotLightAmongOpaqueParticlesBlocksWithinBound) {
    expectWithinBound(kSpotInOpaqueCloud, runCase(context(), kSpotInOpaqueCloud), MediaMode::Blocks, kDefaultErrorBound);
}

// ── A spot light beside opaque sub-pixel particles ───────────────────────────────────────────
// 2000 particles of 4–8 mm, each of optical depth ~1e4 through its centre, around a spot light, on
// black with a faint ambient; g = −0.5 (unseen variant 2 of seed 11, kept here). What is lit is
// two or three pixels where a camera ray grazes a particle 0.6–0.7 m from the spot.
// What could go wrong: the light slices hold optical depth at planes 4 cm apart and at texel
// centres wider than these particles, read linearly between them, so a particle's own τ 1e4 is
// spread over its slice interval and the texels around it, and its lit skin is shadowed by itself
// (both modes: those pixels black, rel-RMSE 47×). A block of such particles is no smooth medium:
// shaded at uniform points of its [front, back] with one transmittance each, the lit pixels stayed
// 15% too dark and 40% too bright with the own shadow fixed (RMS-relative error 29%).
// What prevents it: shaders/media/common/own_optical_depth.glsl particleLightDepth (what the slices hold
// of the particle itself is recomputed, taken out and replaced by its exact optical depth where
// they do not resolve it); block_own_optical_depth.glsl does the same for a block's particles,
// and block_lighting.glsl shades such a block from its own particles (listedShadingPoint and the
// layer integral).
// Bound: 15% of RMS-relative error: the image is sparse (its RMS is ~50× its mean luminance, so
// rel-RMSE reads a pixel's 1% as 50%; stability_harness.h boundedError). Measured: particles 2.6%,
// blocks 1.2% (rel-RMSE 126% and 58%).
const HardCase kSpotBesideOpaqueSpecks{.name = "spot_beside_opaque_specks", .scene = "spot_beside_opaque_specks.gltf"};

TEST_F(StabilityTest, SpotBesideOpaqueSpecksStaysFinite) {
    expectFiniteAndClean(kSpotBesideOpaqueSpecks, runCase(context(), kSpotBesideOpaqueSpecks));
}
TEST_F(StabilityTest, SpotBesideOpaqueSpecksParticlesWithinBound) {
    expectWithinBound(kSpotBesideOpaqueSpecks, runCase(context(), kSpotBesideOpaqueSpecks), MediaMode::Particles, kDefaultErrorBound);
}
TEST_F(StabilityTest, SpotBesideOpaqueSpecksBlocksWithinBound) {
    expectWithinBound(kSpotBesideOpaqueSpecks, runCase(context(), kSpotBesideOpaqueSpecks), MediaMode::Blocks, kDefaultErrorBound);
}

// ── The glory of a dense particle, seen along the sun ────────────────────────────────────────
// One particle of optical depth 1e4 and radius 0.7 m over the ground, the camera looking straight
// down with the sun behind it; g = −0.99 (unseen variant 4 of seed 23, kept here). Its glory, the
// backscatter peak of ~690 at the anti-solar point, is most of the image.
// What could go wrong: the slice planes are 4 cm apart, about R/17, yet each interval holds
// thousands of the particle's optical depth; read linearly between planes, its own τ rises across
// its lit skin as a chord over a cliff, and the glory came out at 18 (particles) and the ambient
// (blocks).
// What prevents it: own_optical_depth.glsl slicesResolve counts a particle of which a slice
// interval or texel holds more than an optical depth of 2 as unresolved, so its own share is made
// exact (particleLightDepth; for blocks, blocksOfUnresolvedParticles and the BLOCK_OWN_PARTICLES
// build).
// Bound: 15% of RMS-relative error (the image is sparse: RMS 12× its mean luminance). Measured:
// particles 0.03%, blocks 0.005% (rel-RMSE 0.30% and 0.06%).
const HardCase kGloryOfDenseParticle{.name = "glory_of_dense_particle", .scene = "glory_of_dense_particle.gltf"};

TEST_F(StabilityTest, GloryOfDenseParticleStaysFinite) {
    expectFiniteAndClean(kGloryOfDenseParticle, runCase(context(), kGloryOfDenseParticle));
}
TEST_F(StabilityTest, GloryOfDenseParticleWithinBound) {
    const CaseRun& run = runCase(context(), kGloryOfDenseParticle);
    expectWithinBound(kGloryOfDenseParticle, run, MediaMode::Particles, kDefaultErrorBound);
    expectWithinBound(kGloryOfDenseParticle, run, MediaMode::Blocks, kDefaultErrorBound);
}

// ── A dense cloud top seen along the sun ─────────────────────────────────────────────────────
// 150 overlapping particles of 60–120 m, the densest column of optical depth 1e4, seen straight
// down with the sun behind the camera; g = −0.5 (unseen variant 4 of seed 25, kept here). Every
// point the camera sees is lit; the top's first optical depth is a few metres deep.
// What could go wrong: particles are composited in back-to-front order as whole layers, each lit
// at its own front. Sorted by their centres, a 120 m particle whose front lies 50 m in front of a
// 65 m one's was drawn behind it: every layer then lay behind another's dense tail, in the light's
// shadow of it, and the lit top came out at the ambient over 40 pixels (particles 16.9%).
// What prevents it: particle_buffer.cpp sorts by the distance to where each particle's seen light
// lies (visibleDepthOffset: the centre for a thin particle, towards its front for a dense one);
// blocks composite a block's particles along each ray in one impostor and keep its mass in order.
// Bound: 15%. Measured: particles 13.4%, blocks 12.6%. What is left is the same misorder between
// particles of equal size whose fronts interleave, which one order per particle cannot remove.
const HardCase kCloudTopAlongSun{.name = "cloud_top_along_sun", .scene = "cloud_top_along_sun.gltf"};

TEST_F(StabilityTest, CloudTopAlongSunStaysFinite) { expectFiniteAndClean(kCloudTopAlongSun, runCase(context(), kCloudTopAlongSun)); }
TEST_F(StabilityTest, CloudTopAlongSunWithinBound) {
    const CaseRun& run = runCase(context(), kCloudTopAlongSun);
    expectWithinBound(kCloudTopAlongSun, run, MediaMode::Particles, kDefaultErrorBound);
    expectWithinBound(kCloudTopAlongSun, run, MediaMode::Blocks, kDefaultErrorBound);
}

// ── Inside a dense particle, looking into the sun ────────────────────────────────────────────
// One particle of optical depth 30, the camera inside it 1e5 m from the origin, looking straight
// up into the sun; g = 0.99 (unseen variant 7 of seed 15, kept here).
// What could go wrong: a particle is composited as one layer lit at one shading point, with e^−τl
// of the light's optical depth there. Along the sun τl falls exactly as the view's optical depth
// grows, so every point of the ray sends the same light, and e^−τl at one point (Jensen's gap)
// made the phase peak 3× too dark (particles 30% rel-RMSE).
// What prevents it: shaders/media/common/lighting.glsl layerLightTransmittance integrates e^−τl over the
// layer in closed form with τl linear in the view's optical depth (from the slices at the layer's
// entry and shading point). Blocks shade two pieces per block and erred 8% before it.
// Bound: 15%. Measured: particles 0.67%, blocks 4.3%.
const HardCase kInsideTowardsSun{.name = "inside_towards_sun", .scene = "inside_towards_sun.gltf"};

TEST_F(StabilityTest, InsideDenseParticleTowardsSunStaysFinite) {
    expectFiniteAndClean(kInsideTowardsSun, runCase(context(), kInsideTowardsSun));
}
TEST_F(StabilityTest, InsideDenseParticleTowardsSunParticlesWithinBound) {
    expectWithinBound(kInsideTowardsSun, runCase(context(), kInsideTowardsSun), MediaMode::Particles, kDefaultErrorBound);
}
TEST_F(StabilityTest, InsideDenseParticleTowardsSunBlocksWithinBound) {
    expectWithinBound(kInsideTowardsSun, runCase(context(), kInsideTowardsSun), MediaMode::Blocks, kDefaultErrorBound);
}
// layer_light=off takes the light at one point per particle again: what the integral fixes.
TEST_F(StabilityTest, InsideDenseParticleTowardsSunNeedsTheLayerIntegral) {
    HardCase onePoint = kInsideTowardsSun;
    onePoint.name = "inside_towards_sun_layer_light_off";
    onePoint.settings = {"layer_light=off"};
    EXPECT_GT(runCase(context(), onePoint).particles.error.relRmse, 5.0 * runCase(context(), kInsideTowardsSun).particles.error.relRmse);
}

// ── g = ±0.99 ────────────────────────────────────────────────────────────────────────────────
// Two clouds, g = +0.99 (left) and g = −0.99 (right), under a low sun; camera "towards_sun" looks
// into it (forward peak), "away_from_sun" has the sun behind it (the antisolar point, where the
// g = −0.99 phase function peaks at p = 1584 /sr, is in view).
// What could go wrong: 1 + g² − 2g cos θ = (1 − |g|)² = 1e-4 at the peak loses digits in float
// and would be 0 (Inf phase) for |g| → 1; a τ-weighted mean g of a block could leave (−1, 1); any
// radiance error near the peak is multiplied by ~1600.
// What prevents it: optics.h / optics.glsl henyeyGreenstein (denominator clamped at 1e-8 in GLSL;
// the parser refuses |g| ≥ 1); block_composite.frag clamps a block's g to ±0.999; the phase is
// evaluated per pixel ray in both modes, so the peak sits at the same pixels as in the reference.
// Block impostors would spread optical depth a texel past the silhouette (≈ 4300 × τ of radiance
// there) and blur it inside: impostor texels carry an edge distance whose bilinear read cuts
// optical depth to zero outside every particle (block_data.glsl readImpostor), and blocks of
// particles under 4 texels in radius get one texel per pixel (impostor_atlas.cpp tileSizes).
// Bound: 15%. Measured: towards_sun particles 0.69%, blocks 0.44%; away_from_sun particles 1.2%,
// blocks 1.7% (blocks 7.5% before their shading pieces were weighted by mass; 35% with neither the
// edge cut nor the per-pixel tiles, 28% with the edge cut alone).
const HardCase kPhaseTowardsSun{.name = "phase_towards_sun", .scene = "phase_extremes.gltf", .camera = "towards_sun"};
const HardCase kPhaseAwayFromSun{.name = "phase_away_from_sun", .scene = "phase_extremes.gltf", .camera = "away_from_sun"};

TEST_F(StabilityTest, PhaseG099TowardsSunStaysFinite) { expectFiniteAndClean(kPhaseTowardsSun, runCase(context(), kPhaseTowardsSun)); }
TEST_F(StabilityTest, PhaseG099TowardsSunWithinBound) {
    const CaseRun& run = runCase(context(), kPhaseTowardsSun);
    expectWithinBound(kPhaseTowardsSun, run, MediaMode::Particles, kDefaultErrorBound);
    expectWithinBound(kPhaseTowardsSun, run, MediaMode::Blocks, kDefaultErrorBound);
}
TEST_F(StabilityTest, PhaseG099AwayFromSunStaysFinite) {
    expectFiniteAndClean(kPhaseAwayFromSun, runCase(context(), kPhaseAwayFromSun));
}
TEST_F(StabilityTest, PhaseG099AwayFromSunWithinBound) {
    const CaseRun& run = runCase(context(), kPhaseAwayFromSun);
    expectWithinBound(kPhaseAwayFromSun, run, MediaMode::Particles, kDefaultErrorBound);
    expectWithinBound(kPhaseAwayFromSun, run, MediaMode::Blocks, kDefaultErrorBound);
}

}  // namespace
}  // namespace nimbus::stability
