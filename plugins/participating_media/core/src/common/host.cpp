#include "nimbus/media/host.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_access.hpp>

#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

OccluderBox occluderBox(const glm::dmat4& world, const glm::dvec3& lo, const glm::dvec3& hi) {
    const glm::dvec3 localCentre = 0.5 * (glm::dvec3(lo) + glm::dvec3(hi)), localHalf = 0.5 * (glm::dvec3(hi) - glm::dvec3(lo));
    OccluderBox box;
    box.centre = glm::dvec3(world * glm::dvec4(localCentre, 1.0));
    const glm::dmat3 linear(world);
    double length[3];
    for (int k = 0; k < 3; ++k) length[k] = glm::length(linear[k]);
    const bool orthogonal = std::abs(glm::dot(linear[0], linear[1])) <= 1e-9 * length[0] * length[1] &&
                            std::abs(glm::dot(linear[0], linear[2])) <= 1e-9 * length[0] * length[2] &&
                            std::abs(glm::dot(linear[1], linear[2])) <= 1e-9 * length[1] * length[2];
    if (orthogonal && length[0] > 0.0 && length[1] > 0.0 && length[2] > 0.0) {
        for (int k = 0; k < 3; ++k) {
            box.axis[k] = linear[k] / length[k];
            box.half[k] = localHalf[k] * length[k];
        }
    } else {
        for (int k = 0; k < 3; ++k) box.half[k] = glm::dot(glm::abs(glm::row(linear, k)), localHalf);  // axis-aligned around it
    }
    return box;
}

double squaredDistance(const OccluderBox& box, const glm::dvec3& p) {
    const glm::dvec3 d = p - box.centre;
    double outside = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double excess = std::max(std::abs(glm::dot(d, box.axis[k])) - box.half[k], 0.0);
        outside += excess * excess;
    }
    return outside;
}

glm::dvec3 axisAlignedHalf(const OccluderBox& box) {
    glm::dvec3 hull(0.0);
    for (int k = 0; k < 3; ++k) hull += glm::abs(box.axis[k]) * box.half[k];
    return hull;
}

void LightSlices::bind(GLuint viewsBinding, GLuint slicesUnit) const {
    if (views != 0) glBindBufferBase(GL_UNIFORM_BUFFER, viewsBinding, views);
    if (texture != 0) glBindTextureUnit(slicesUnit, texture);
}

void LightSlices::bind() const { bind(kSliceViewsBinding, kSlicesUnit); }

}  // namespace nimbus::media
