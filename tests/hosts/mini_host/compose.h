#pragma once
// The last pass and the way out: media over opaque into an RGBA32F output, read back top row
// first, written as EXR.
#include <filesystem>
#include <vector>

#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/view.h"

namespace mini {

// A media layer as the plugin returns it (nimbus::media::MediaLayer): rgb premultiplied in-scattered
// radiance, a view transmittance; below the frame's size it comes with the view depth each texel
// used, and is upsampled with depth awareness, except where its edges came drawn at full
// resolution (within edgeRect, where their alpha is ≥ 0).
struct MediaLayerRef {
    GLuint color = 0;
    int width = 0, height = 0;
    GLuint depthUsed = 0;
    float edgeThreshold = 0.2f;
    GLuint edges = 0;
    glm::ivec4 edgeRect{0};
};

class Composer {
public:
    Composer();
    // output = layer.rgb + layer.a · opaque, or opaque alone when `layer` is null or empty.
    // `sceneDepth` (standard or reversed for `view`'s planes) serves the upsampling of a reduced layer.
    void compose(GLuint opaqueColor, GLuint sceneDepth, const nimbus::gpu::View& view, bool standardDepth, const MediaLayerRef* layer);
    GLuint output() const { return output_.id(); }

private:
    nimbus::gpu::Program program_;
    nimbus::gpu::Sampler clamped_;  // depth used: textureGather past the edges clamps
    nimbus::gpu::VertexArray emptyVertexArray_;  // core profile needs one bound to draw
    nimbus::gpu::Framebuffer framebuffer_;
    nimbus::gpu::Texture output_;
};

// An RGBA32F texture's level 0 as floats, row 0 at the top (GL stores the bottom row first).
std::vector<float> readRgbaTopDown(GLuint texture, int width, int height);

// RGBA float EXR; throws std::runtime_error naming the file when it cannot be written.
void writeExr(const std::filesystem::path& file, int width, int height, const std::vector<float>& rgba);

}  // namespace mini
