#pragma once
// The plugin's own uniform blocks for a frame (gpu/frame_layout.h Frame, Lights, ShadowViews, and
// MediaSliceViews), packed from the HostFrame: the plugin never reads the host's buffers.
#include <vector>

#include "nimbus/gpu/frame_layout.h"
#include "nimbus/media/gpu_bindings.h"
#include "nimbus/media/host.h"

namespace nimbus::media {

// Refuses (InputError) a light with six shadow views that are not gpu::makeLightViews' cube faces in
// its order: the shaders read such a light's faces by a swizzle (gpu::cubeFaceView), not their
// matrices, so a host's faces turned otherwise would be misread without a word.
void checkCubeFaces(const HostShadowMaps& shadows);

// Where the slice array holds the lamps' views (slices/slice_view.h sliceTexels): every perspective
// view at `lampTexels` per side in the first texels of its layers, the others whole. 0: whole too.
struct SliceArrayLayout {
    int arrayTexels = 0;
    int lampTexels = 0;
};

class FrameBlocks {
public:
    FrameBlocks();
    // Packs now; upload() writes them (when the graph runs, after the host's previous frame).
    void pack(const HostFrame& frame, const std::vector<gpu::GpuLightView>& sliceViews, const std::vector<glm::ivec2>& perLight,
              SliceArrayLayout layout = {});
    // The multiple-scattering model's block and environment grid with its directional part
    // (environment 0: the frame is single scattering).
    void packScattering(const GpuScattering& scattering, GLuint environment, GLuint directional);
    void upload() const;
    void bind() const;  // Frame, Lights, ShadowViews, MediaSliceViews (and MediaScattering) at their points
    GLuint sliceViews() const { return sliceViews_.id(); }

private:
    gpu::GpuFrame frame_{};
    std::vector<gpu::GpuLight> lights_;
    std::vector<gpu::GpuLightView> shadowViews_;
    std::vector<glm::ivec4> perLight_;
    std::vector<gpu::GpuLightView> views_;
    glm::ivec4 sliceHeader_{0};
    GpuScattering scattering_{};
    GLuint environment_ = 0, directional_ = 0;
    gpu::Buffer frameBuffer_, lightsBuffer_, shadowViewsBuffer_, sliceViews_, scatteringBuffer_;
};

}  // namespace nimbus::media
