#pragma once
// Where the particles are, as the frame's planning asks it: their bounds, how much of the image
// their billboards cover, and whether a lamp or the eye lies among them. The renderer and the
// techniques choose resolutions and shading variants from these.
//
// Does not: touch the GPU.
#include <cstdint>
#include <span>
#include <vector>

#include "nimbus/base/aabb.h"
#include "nimbus/gpu/view.h"
#include "nimbus/media/host.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/volume.h"

namespace nimbus::media {

// The particles' billboards on screen, estimated on the CPU: how many times over they cover the
// image (Σ billboard area / image area, each clipped to the screen: what the splat floor pays for),
// and their half size in pixels, weighted by that area.
struct SplatFootprint {
    double coverage = 0.0;
    double radiusPixels = 0.0;
};
// `which` (one per particle, nonzero: in): only those particles; null: all.
SplatFootprint splatFootprint(const ParticleSet& particles, const gpu::View& view, const std::vector<std::uint8_t>* which = nullptr);

// The window pixels (x, y from the lower left, width, height) that bound the spheres of the
// particles flagged in `which` (one per particle, nonzero: in), grown by `margin` pixels and
// clipped to the view; width 0 where none is flagged or on screen. Conservative: a sphere around
// or behind the eye's plane takes the whole view.
glm::ivec4 billboardRect(const ParticleSet& particles, const std::vector<std::uint8_t>& which, const gpu::View& view, int margin);

// Per particle (1/0): whether its sphere's pixels, as billboardRect bounds them, meet `rect`.
std::vector<std::uint8_t> billboardsMeeting(const ParticleSet& particles, const gpu::View& view, glm::ivec4 rect);

// Where a mesh reaches into the medium on screen: over the boxes that come within `reach` radii of
// some particle's centre, the union of each box's rect and its near particles' (billboardRect),
// grown by `margin`; width 0 where none does.
glm::ivec4 nearMeshRect(const std::vector<OccluderBox>& meshes, const ParticleSet& particles, double reach, const gpu::View& view, int margin);

// Mixed resolution (MediaTechnique::edgeRect): where a media target of `targetSize` texels is
// drawn again at full resolution, nearMeshRect at kEdgeReach grown by one reduced texel (the
// upsampling's taps); width 0 at full resolution or where no mesh's box enters a particle's sphere.
glm::ivec4 meshEdgeRect(const std::vector<OccluderBox>& meshes, const ParticleSet& particles, const gpu::View& view, glm::ivec2 targetSize);
// A mesh's box entering a particle's sphere: the seam's own definition. Two radii gave the same
// seam error on wing_through_cloud and cumulus_aircraft over a 43% larger rect on the wing
// (docs/design-notes.md).
inline constexpr double kEdgeReach = 1.0;

// The window pixels of a box's corners, grown by `margin` and clipped to the view; the whole view
// where a corner lies behind the near plane.
glm::ivec4 boxRect(const OccluderBox& box, const gpu::View& view, int margin);

// The pixels two rects (x, y, width, height) share; width 0 where none.
glm::ivec4 intersectRects(glm::ivec4 a, glm::ivec4 b);
// `rect` grown by `margin` pixels each way and clipped to the view; width 0 stays so.
glm::ivec4 growRect(glm::ivec4 rect, int margin, const gpu::View& view);
// The smallest rect holding both (one of width 0 holds nothing).
glm::ivec4 unionRects(glm::ivec4 a, glm::ivec4 b);

// The pixels outside which the medium draws nothing: the particles' spheres (billboardRect) and
// each volume's box, grown by `margin` and clipped to the view; width 0 where none is on screen.
// A reduced target is upsampled and composed only there (MediaLayer::coverRect).
glm::ivec4 mediumRect(const ParticleSet& particles, const std::vector<Volume>& volumes, const gpu::View& view, int margin);

// Within this many radii of a point or spot light (or across a spot's cone edge) a particle's
// splats take its light per fragment, with the near field's quadrature where a ray passes within
// two deviations (2R/3) of it (particles_technique.cpp, splat_source.glsl). Beyond about 1.7 radii
// no ray through a particle passes that close; campfire errs as before at 2, 22% more at 1.5
// (docs/design-notes.md).
inline constexpr double kLampReach = 2.0;

// The images (ndc) of the point lights among the particles (within kLampReach radii of one) in
// front of the eye. Around each, the light it scatters peaks as 1/distance, which a reduced
// target's bilinear upsampling cannot follow: campfire at ¼ erred 21% against 4.4% at full
// resolution, nearly all of it there. So mixed resolution draws the pixels within the upsampling's
// reach of each image again at full resolution (4.7%; docs/design-notes.md).
std::vector<glm::dvec2> lampImages(const ParticleSet& particles, const std::vector<Light>& lights, const gpu::View& view);
// Those pixels: each image's square, grown by `margin` and clipped to the view; `rect` their union,
// `pixels` the sum of the squares' areas, which the union's may far exceed where two lamps lie far
// apart on screen. Width 0 where there is none.
struct LampPeaks {
    glm::ivec4 rect{0};
    long long pixels = 0;
};
LampPeaks lampPeaks(const std::vector<glm::dvec2>& images, const gpu::View& view, int margin);
// Whether the peaks are worth drawing again through one rect (the edge target is one): its area at
// most kPeakRectSlack × their own at ¼'s reach. Two lamps at opposite sides of the image would
// otherwise redraw everything between them; such a frame keeps full resolution instead.
bool lampPeaksCompact(const std::vector<glm::dvec2>& images, const gpu::View& view);
inline constexpr double kPeakRectSlack = 4.0;

// media_scale=auto: 1 unless the billboards cover the pixels the layer is composed over (`composed`,
// mediumRect's share of the image, where the upsampling pays) more than kHalfScaleCoverage times
// over, so fill dominates, and no lamp's light would be blurred (`lampBlurred`: a spot light among
// the particles, or a point light whose peak is not drawn again at full resolution); then as low
// as keeps kAutoScaleRadiusTexels across a typical billboard's half size, within [¼, ½]. The kernel
// is smooth over a billboard, so the depth-aware upsampling loses next to nothing there
// (docs/design-notes.md). Billboards that ½ would leave with fewer texels stay at full resolution:
// a reduced target blurs them away.
float automaticMediaScale(const SplatFootprint& footprint, double composed, bool lampBlurred);
inline constexpr double kHalfScaleCoverage = 2.5;
inline constexpr double kAutoScaleRadiusTexels = 8.0;
// What a point light's own particles keep (MediaRenderer::lampLitFootprint): its light varies within
// each of them. Campfire's fire particles are far smaller than its smoke's. With the smoke's 8 texels
// it erred 10% at 320×180 (4.2% at full resolution), 5.6% at 640×360 (4.4%), 4.7% at 1280×720 (4.4%),
// within the fire around the lamp; with 16, 320×180 and 640×360 stay at full resolution and
// 1280×720 takes 0.37 and errs 4.5%.
inline constexpr double kLampLitRadiusTexels = 16.0;
// impostor_scale=auto (blocks): as few impostor texels per media texel as keep
// kAutoImpostorRadiusTexels across a typical billboard's half size (the kernel's s = R/3 then
// spans two), within [¼, ½], rounded up to eighths so that a camera moving a little keeps the
// scale and with it the impostors it may read again. `radiusTexels`: SharedFrame::radiusTexels.
float automaticImpostorScale(double radiusTexels);
inline constexpr double kAutoImpostorRadiusTexels = 6.0;

// Below this many billboard pixels per particle, per-particle lighting takes one ray per particle:
// a fit across them has nothing to follow (docs/design-notes.md).
inline constexpr double kConstantSplatPixels = 2.0;

// Whether a point or spot light (`kind`) lies inside `bounds` (the particles').
bool lampAmongParticles(const std::vector<Light>& lights, const Aabb& bounds, gpu::LightKind kind);

// Whether a point or spot light lies inside a particle that takes more than a tenth of a ray
// through its centre (a column over kLampMediumColumn): the particles mode's exact_near_lamps.
inline constexpr double kLampMediumColumn = 0.1;
bool lampInsideMedium(const ParticleSet& particles, const std::vector<Light>& lights);

// Whether some mesh's box meets `bounds` (the medium's), taken as the axis-aligned box around it:
// where a mesh may reach into the medium (MediaRenderSettings::slicesNearMeshes).
bool meshReachesInto(const std::vector<OccluderBox>& meshes, const Aabb& bounds);

// Per particle (1/0): whether some mesh's box (HostFrame::occluders) comes within `reach` radii of
// its centre (reach 1: into its sphere).
std::vector<std::uint8_t> particlesNearMeshes(const std::vector<OccluderBox>& meshes, const ParticleSet& particles, double reach);

// Whether the box spans the medium's `bounds` across its two longest axes (as the axis-aligned box
// around it), as a ground or a wall through the medium does: seen from one side only, it cuts the
// particles it enters without lighting their visible part unevenly, as a wing inside a cloud does.
bool boxSpansMedium(const OccluderBox& box, const Aabb& bounds);

// Per particle (1/0): whether one of the point or spot lights `lamps` (indices into `lights`; −1
// ends the list) lies within `reach` radii of its centre, where its 1/d² changes across the
// particle faster than a fit over the billboard follows, or whether a spot's cone edge (from the
// inner to the outer angle) crosses its sphere.
std::vector<std::uint8_t> particlesNearLamps(const ParticleSet& particles, const std::vector<Light>& lights, std::span<const int> lamps,
                                             double reach);

// Per particle (1/0): whether the depth test alone clips its splat exactly, with no scene-depth
// fetch (particle_splat_pass.cpp): its billboard is a quad through the centre, and a pixel's ray
// meets that plane within the half size of the quad of the centre, as its chord is, so where no
// mesh box comes within that distance a surface lies in front of both or behind both. Not where
// the quad covers the screen (the eye in or near the sphere, or it crosses the near plane), as
// billboard.glsl decides with a margin.
std::vector<std::uint8_t> particlesClearOfMeshes(const std::vector<OccluderBox>& meshes, const ParticleSet& particles, const gpu::View& view);

// Whether the eye (an orthographic camera's plane) lies inside some particle's sphere.
bool eyeInsideMedium(const ParticleSet& particles, const gpu::View& view);

// World bounds of the particle spheres.
Aabb particleBounds(const ParticleSet& particles);

// Whether anything of the medium is there to draw: particles or volumes.
inline bool hasMedium(const ParticleSet& particles, const std::vector<Volume>* volumes) {
    return !particles.empty() || (volumes != nullptr && !volumes->empty());
}

}  // namespace nimbus::media
