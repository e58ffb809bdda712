#pragma once
// The viewport's display pass: turns the renderer's linear output into the 8-bit sRGB texture the
// viewport window shows, on the GPU, so a frame needs no read-back or CPU encoding.
//
// Does not: tone-map (the viewport shows what a PNG from `sandbox render` shows).
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/fullscreen_pass.h"

namespace nimbus::sandbox::editor {

class ViewportDisplay {
public:
    ViewportDisplay();
    // Encodes `radiance` (RGBA float, GL row order) into display(), resized to match.
    void encode(const gpu::Texture& radiance);
    const gpu::Texture& display() const { return display_; }

private:
    gpu::FullscreenPass pass_;
    gpu::Framebuffer framebuffer_;
    gpu::Texture display_;
};

}  // namespace nimbus::sandbox::editor
