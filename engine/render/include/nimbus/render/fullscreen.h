#pragma once
// A viewport-covering triangle for full-screen passes (shaders/fullscreen.vert makes the vertices).
#include "nimbus/gpu/gl_objects.h"

namespace nimbus::render {

class FullscreenTriangle {
public:
    FullscreenTriangle() : vertexArray_(gpu::createVertexArray()) {}
    void draw() const {
        glBindVertexArray(vertexArray_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
    }

private:
    gpu::VertexArray vertexArray_;  // core profile needs one bound, even with no attributes
};

}  // namespace nimbus::render
