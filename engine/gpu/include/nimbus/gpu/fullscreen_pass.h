#pragma once
// A program drawn once over a whole target through shaders/fullscreen.vert's covering triangle:
// the shape of every per-texel pass (a depth re-encoded, the depth a reduced target used, a
// stencil from a mask, a running sum over slabs, the compose). Each draw declares its state.
//
// Does not: own the target or bind the program's inputs (the pass does, on program()).
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/pipeline_state.h"

namespace nimbus::gpu {

class FullscreenPass {
public:
    explicit FullscreenPass(const std::string& fragment, std::vector<std::string> defines = {});
    GLuint program() const { return program_.id(); }
    // Binds `framebuffer` with a size.x × size.y viewport, applies `state`, uses the program and draws.
    void draw(GLuint framebuffer, glm::ivec2 size, const PipelineState& state = {}) const;

private:
    Program program_;
    VertexArray vertexArray_ = createVertexArray();  // core profile needs one bound, even with no attributes
};

// A framebuffer drawing into level 0 of `texture` alone: as colour attachment 0, or as the depth
// (and stencil) attachment when `format` is a depth format.
Framebuffer singleTargetFramebuffer(GLuint texture, GLenum format);

}  // namespace nimbus::gpu
