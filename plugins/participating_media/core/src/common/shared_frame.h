#pragma once
// What every media mode shares in one frame, planned by the renderer (frame/media_renderer.cpp)
// before it calls the frame's technique: the particles on the GPU, the plugin's uniform blocks,
// the media target, the particles' bounds and footprint, and the light slice views.
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "common/environment_grid.h"
#include "common/frame_blocks.h"
#include "common/media_target.h"
#include "common/particle_buffer.h"
#include "common/volume_buffer.h"
#include "nimbus/base/aabb.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/light_views.h"

namespace nimbus::media {

// One light view's slices: the view, the slice range and count, and where its layers start.
struct SliceView {
    gpu::LightView view;
    glm::vec3 lightOrigin{0.0f};  // origin-relative light position (perspective views)
    int slices = 4;
    int firstLayer = 0;
    // Texels per side of this view (0: the slice array's). A lamp's cube faces may need fewer than
    // the array holds for the sun: every slice pass draws such a view into the first texels of its
    // layers, and the rest of them stays zero (slices/slice_view.h sliceTexels).
    int resolution = 0;
    // A crop (planning/slice_crop.h): the index of the whole view whose optical depth at this view's
    // first plane seeds it, so its first slab takes no particles; −1 for a whole view.
    int seedView = -1;
};

struct SharedFrame {
    // Made with the first frame that draws something (they need the GL context).
    std::unique_ptr<ParticleGpuBuffer> buffer;
    std::unique_ptr<FrameBlocks> blocks;
    std::unique_ptr<VolumeGpuBuffer> volumes;  // made with the first frame that has a volume
    std::size_t volumeCount = 0;               // this frame's (the buffer is filled when the graph runs)
    MediaTarget target;
    Aabb bounds;                        // the particle spheres' and the volumes', world space
    double coverage = 0.0;              // how many times over the billboards cover the image
    double radiusTexels = 0.0;          // a typical billboard's half size in media target texels
    std::vector<SliceView> sliceViews;  // every light's, in GraphFrame::sliceViews order
    int sliceResolution = 0;            // texels per side of every slice
    EnvironmentGrid environment;        // multiple scattering: this frame's (empty: single)
    gpu::Texture environmentTexture;    // its GPU copy, RGBA32F, linear
    gpu::Texture directionalTexture;    // its directional part, RGBA32F, linear
};

}  // namespace nimbus::media
