#pragma once
// The fill-rate floor of DESIGN.md §6: how long the same GL implementation takes to blend a given
// number of covered pixels into an RGBA32F target with a trivial shader. A renderer's frame time
// divided by this says how far it is from the limit of the rasteriser itself.
#include <cstdint>

#include "nimbus/gpu/gl_objects.h"

namespace nimbus::sandbox {

class FillRateFloor {
public:
    FillRateFloor(int width, int height);  // needs a current GL context
    // Median milliseconds (over `repeats` GPU-synchronised runs) to blend `fragments` pixels.
    double measure(std::uint64_t fragments, int repeats = 20);

private:
    void draw(std::uint64_t fragments);

    int width_, height_;
    gpu::Texture target_;
    gpu::Framebuffer framebuffer_;
    gpu::Program program_;
    gpu::VertexArray vertexArray_;
};

}  // namespace nimbus::sandbox
