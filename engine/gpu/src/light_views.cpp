#include "nimbus/gpu/light_views.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "nimbus/gpu/view.h"

namespace nimbus::gpu {
namespace {

// An orthonormal basis looking along `forward`; `upHint` is replaced when nearly parallel.
glm::dmat4 lookAlong(const glm::dvec3& eye, const glm::dvec3& forward, glm::dvec3 upHint) {
    const glm::dvec3 f = glm::normalize(forward);
    if (std::abs(glm::dot(f, glm::normalize(upHint))) > 0.99) upHint = std::abs(f.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
    const glm::dvec3 r = glm::normalize(glm::cross(f, upHint));
    const glm::dvec3 u = glm::cross(r, f);
    glm::dmat4 m(1.0);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = r[c];
        m[c][1] = u[c];
        m[c][2] = -f[c];
    }
    m[3][0] = -glm::dot(r, eye);
    m[3][1] = -glm::dot(u, eye);
    m[3][2] = glm::dot(f, eye);
    return m;
}

std::array<glm::dvec3, 8> corners(const Aabb& b, const glm::dvec3& origin) {
    std::array<glm::dvec3, 8> c;
    for (int i = 0; i < 8; ++i)
        c[static_cast<std::size_t>(i)] = glm::dvec3(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z) - origin;
    return c;
}

LightView perspectiveView(const glm::dvec3& eye, const glm::dvec3& forward, const glm::dvec3& up, double fovY,
                          const Aabb& bounds, const glm::dvec3& origin, double range) {
    LightView v;
    const glm::dmat4 view = lookAlong(eye, forward, up);
    double farthest = 0.0;
    for (const auto& c : corners(bounds, origin)) farthest = std::max(farthest, -(view * glm::dvec4(c, 1.0)).z);
    if (range > 0.0) farthest = std::min(farthest, range);
    const double zfar = std::max(farthest * 1.01, 1e-3);
    const double znear = std::max(zfar * 1e-4, 1e-4);
    v.view = glm::mat4(view);
    v.viewProjection = reversedPerspective(fovY, 1.0, znear, zfar) * glm::mat4(view);
    v.perspective = true;
    v.depthNear = static_cast<float>(znear);
    v.depthFar = static_cast<float>(zfar);
    v.halfExtent = glm::vec2(static_cast<float>(std::tan(fovY * 0.5)));
    return v;
}

}  // namespace

int cubeFace(const glm::vec3& d) {
    const glm::vec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
    return d.z >= 0.0f ? 4 : 5;
}

glm::vec3 cubeFaceView(int face, const glm::vec3& d) {
    switch (face) {
        case 0: return {-d.z, -d.y, d.x};
        case 1: return {d.z, -d.y, -d.x};
        case 2: return {d.x, d.z, d.y};
        case 3: return {d.x, -d.z, -d.y};
        case 4: return {d.x, -d.y, d.z};
        default: return {-d.x, -d.y, -d.z};
    }
}

bool isCubeFaceView(int face, const LightView& v) {
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 d(0.0f);
        d[axis] = 1.0f;
        const glm::vec3 want = cubeFaceView(face, d);
        const glm::vec3 got = glm::vec3(v.view * glm::vec4(d, 0.0f));
        if (glm::any(glm::greaterThan(glm::abs(got - glm::vec3(want.x, want.y, -want.z)), glm::vec3(1e-4f)))) return false;
    }
    return true;
}

std::vector<LightView> makeLightViews(const PunctualLight& light, const Aabb& bounds, const glm::dvec3& origin) {
    std::vector<LightView> views;
    if (bounds.empty()) return views;
    const glm::dvec3 lightPos = light.position - origin;
    switch (light.kind) {
        case LightKind::Directional: {
            const glm::dvec3 centre = bounds.center() - origin;
            const double radius = 0.5 * glm::length(bounds.extent()) + 1e-3;
            // Eye on the light side of the bounds; the fit below tightens x/y and depth.
            const glm::dmat4 view = lookAlong(centre - light.direction * (radius * 2.0), light.direction, glm::dvec3(0, 1, 0));
            glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
            for (const auto& c : corners(bounds, origin)) {
                const glm::dvec3 p = glm::dvec3(view * glm::dvec4(c, 1.0));
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            const double margin = 1e-3 * radius;
            const glm::dvec2 halfSize = 0.5 * glm::dvec2(hi.x - lo.x, hi.y - lo.y) + margin;
            const glm::dvec2 mid = 0.5 * glm::dvec2(hi.x + lo.x, hi.y + lo.y);
            const double znear = std::max(-hi.z - margin, 0.0);
            const double zfar = -lo.z + margin;
            // Recentre the ortho box on the bounds' footprint.
            glm::dmat4 shift(1.0);
            shift[3][0] = -mid.x;
            shift[3][1] = -mid.y;
            LightView v;
            v.view = glm::mat4(shift * view);
            v.viewProjection = reversedOrthographic(halfSize.x, halfSize.y, znear, zfar) * v.view;
            v.perspective = false;
            v.depthNear = static_cast<float>(znear);
            v.depthFar = static_cast<float>(zfar);
            v.halfExtent = glm::vec2(halfSize);
            views.push_back(v);
            break;
        }
        case LightKind::Spot: {
            const double fov = std::min(2.0 * light.outerConeAngle + 0.02, glm::radians(170.0));
            views.push_back(perspectiveView(lightPos, light.direction, glm::dvec3(0, 1, 0), fov, bounds, origin, light.range));
            break;
        }
        case LightKind::Point: {
            const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
            const glm::dvec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
            for (int f = 0; f < 6; ++f)
                views.push_back(perspectiveView(lightPos, axes[f], ups[f], glm::radians(90.0), bounds, origin, light.range));
            break;
        }
    }
    return views;
}

}  // namespace nimbus::gpu
