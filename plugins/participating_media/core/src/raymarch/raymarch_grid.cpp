#include "raymarch/raymarch_grid.h"

namespace nimbus::media {

gpu::Texture makeGridTexture(glm::ivec3 size, GLenum format) {
    gpu::Texture texture({.target = GL_TEXTURE_3D, .format = format, .width = size.x, .height = size.y, .depth = size.z});
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glTextureParameteri(texture.id(), wrap, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return texture;
}

void RaymarchGrid::upload(const VoxelGrid& grid) {
    const bool resized = !scattering_ || scattering_.desc().width != grid.size.x || scattering_.desc().height != grid.size.y ||
                         scattering_.desc().depth != grid.size.z;
    if (resized) {
        scattering_ = makeGridTexture(grid.size, GL_RGBA32F);
        emission_ = makeGridTexture(grid.size, GL_RGBA32F);
        noise_ = makeGridTexture(grid.size, GL_R32F);
    }
    glTextureSubImage3D(scattering_.id(), 0, 0, 0, 0, grid.size.x, grid.size.y, grid.size.z, GL_RGBA, GL_FLOAT, grid.scattering.data());
    glTextureSubImage3D(emission_.id(), 0, 0, 0, 0, grid.size.x, grid.size.y, grid.size.z, GL_RGBA, GL_FLOAT, grid.emission.data());
    const float zero = 0.0f;
    glClearTexImage(noise_.id(), 0, GL_RED, GL_FLOAT, &zero);
}

}  // namespace nimbus::media
