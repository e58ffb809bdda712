#include "viewport/picking.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nimbus::sandbox::editor {
namespace {

struct ViewBasis {
    glm::dvec3 position, forward, up, right;
    double aspect;
    bool orthographic;
    double halfHeight;  // tan(yfov/2) for perspective, ymag for orthographic
};

ViewBasis viewBasis(const assets::ResolvedCamera& camera, int width, int height) {
    ViewBasis b;
    b.position = camera.position();
    b.forward = camera.forward();
    b.up = camera.up();
    b.right = camera.right();
    b.aspect = static_cast<double>(std::max(1, width)) / static_cast<double>(std::max(1, height));
    b.orthographic = camera.params.projection == assets::Projection::Orthographic;
    // Orthographic width follows the image aspect (ymag·W/H), as in the renderers; xmag is ignored.
    b.halfHeight = b.orthographic ? camera.params.ymag : std::tan(0.5 * camera.params.yfov);
    return b;
}

bool finite(const glm::dvec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }

}  // namespace

Ray viewportRay(const assets::ResolvedCamera& camera, glm::dvec2 pixel, int width, int height) {
    const ViewBasis b = viewBasis(camera, width, height);
    const double ndcX = 2.0 * pixel.x / std::max(1, width) - 1.0;
    const double ndcY = 1.0 - 2.0 * pixel.y / std::max(1, height);
    Ray ray;
    if (b.orthographic) {
        ray.origin = b.position + b.right * (b.halfHeight * b.aspect * ndcX) + b.up * (b.halfHeight * ndcY);
        ray.direction = b.forward;
    } else {
        ray.origin = b.position;
        ray.direction = glm::normalize(b.forward + b.right * (ndcX * b.halfHeight * b.aspect) + b.up * (ndcY * b.halfHeight));
    }
    return ray;
}

std::optional<glm::dvec2> projectToViewport(const assets::ResolvedCamera& camera, const glm::dvec3& world, int width,
                                            int height) {
    const ViewBasis b = viewBasis(camera, width, height);
    const glm::dvec3 d = world - b.position;
    const double depth = glm::dot(d, b.forward);
    if (!(depth > 0.0)) return std::nullopt;
    const double scale = b.orthographic ? b.halfHeight : depth * b.halfHeight;
    const double ndcX = glm::dot(d, b.right) / (scale * b.aspect);
    const double ndcY = glm::dot(d, b.up) / scale;
    const glm::dvec2 pixel(0.5 * (ndcX + 1.0) * std::max(1, width), 0.5 * (1.0 - ndcY) * std::max(1, height));
    if (!finite(pixel)) return std::nullopt;
    return pixel;
}

double viewDepth(const assets::ResolvedCamera& camera, const glm::dvec3& world) {
    return glm::dot(world - camera.position(), camera.forward());
}

double worldPerPixel(const assets::ResolvedCamera& camera, double depth, int height) {
    const double h = static_cast<double>(std::max(1, height));
    if (camera.params.projection == assets::Projection::Orthographic) return 2.0 * camera.params.ymag / h;
    return 2.0 * depth * std::tan(0.5 * camera.params.yfov) / h;
}

std::optional<double> intersectAabb(const Ray& ray, const Aabb& box) {
    if (box.empty()) return std::nullopt;
    double tNear = -std::numeric_limits<double>::infinity();
    double tFar = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis], d = ray.direction[axis];
        if (d == 0.0) {
            // Parallel to this slab: inside it everywhere or nowhere (avoids 0·inf = NaN).
            if (o < box.min[axis] || o > box.max[axis]) return std::nullopt;
            continue;
        }
        double t0 = (box.min[axis] - o) / d, t1 = (box.max[axis] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
    }
    if (!(tNear <= tFar) || tFar < 0.0) return std::nullopt;
    return std::max(tNear, 0.0);
}

std::optional<double> intersectSphere(const Ray& ray, const glm::dvec3& centre, double radius) {
    if (!(radius >= 0.0)) return std::nullopt;
    const glm::dvec3 oc = ray.origin - centre;
    const double c = glm::dot(oc, oc) - radius * radius;
    if (c <= 0.0) return 0.0;  // origin inside
    const double a = glm::dot(ray.direction, ray.direction);
    const double b = glm::dot(oc, ray.direction);
    if (!(a > 0.0) || b >= 0.0) return std::nullopt;  // no direction, or moving away from the centre
    const double discriminant = b * b - a * c;
    if (discriminant < 0.0) return std::nullopt;
    // The stable form of the near root (b < 0 here).
    const double t = c / (-b + std::sqrt(discriminant));
    return std::isfinite(t) ? std::optional<double>(t) : std::nullopt;
}

int pick(const Ray& ray, const std::vector<PickTarget>& targets) {
    int best = -1;
    double bestT = std::numeric_limits<double>::infinity();
    for (const PickTarget& target : targets) {
        if (target.sphere && glm::length(ray.origin - target.centre) <= target.radius) continue;  // an icon around the eye
        const std::optional<double> t =
            target.sphere ? intersectSphere(ray, target.centre, target.radius) : intersectAabb(ray, target.box);
        if (t && *t < bestT) {
            bestT = *t;
            best = target.id;
        }
    }
    return best;
}

Aabb transformBox(const Aabb& box, const glm::dmat4& world) {
    Aabb out;
    if (box.empty()) return out;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                           (corner & 4) ? box.max.z : box.min.z);
        out.extend(glm::dvec3(world * glm::dvec4(p, 1.0)));
    }
    return out;
}

}  // namespace nimbus::sandbox::editor
