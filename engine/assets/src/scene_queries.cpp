#include "nimbus/assets/scene_queries.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "animation_sampling.h"
#include "nimbus/base/camera_frame.h"
#include "nimbus/base/error.h"

namespace nimbus::assets {
namespace {

struct Trs {
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scale{1.0};
};

glm::dmat4 composeTrs(const Trs& p) {
    const glm::dmat4 t = glm::translate(glm::dmat4(1.0), p.translation);
    const glm::dmat4 r = glm::mat4_cast(p.rotation);
    return glm::scale(t * r, p.scale);
}

}  // namespace

glm::dvec3 ResolvedCamera::forward() const { return cameraFrame(world).forward; }
glm::dvec3 ResolvedCamera::up() const { return cameraFrame(world).up; }
glm::dvec3 ResolvedCamera::right() const { return cameraFrame(world).right; }

std::vector<bool> nodesInScene(const Scene& scene) {
    std::vector<bool> in(scene.nodes.size(), false);
    std::vector<int> stack(scene.rootNodes.begin(), scene.rootNodes.end());
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        if (n < 0 || static_cast<std::size_t>(n) >= in.size() || in[static_cast<std::size_t>(n)]) continue;
        in[static_cast<std::size_t>(n)] = true;
        for (const int c : scene.nodes[static_cast<std::size_t>(n)].children) stack.push_back(c);
    }
    return in;
}

glm::dmat4 localTransform(const Node& node) {
    if (node.hasMatrix) return node.matrix;
    return composeTrs({node.translation, node.rotation, node.scale});
}

std::vector<glm::dmat4> computeWorldTransforms(const Scene& scene, double timeSeconds) {
    const std::size_t count = scene.nodes.size();
    std::vector<Trs> pose(count);
    for (std::size_t i = 0; i < count; ++i) pose[i] = {scene.nodes[i].translation, scene.nodes[i].rotation, scene.nodes[i].scale};
    // All animations play together; a later channel on the same node and path wins.
    for (const Animation& animation : scene.animations) {
        for (const AnimationChannel& channel : animation.channels) {
            if (channel.node < 0 || static_cast<std::size_t>(channel.node) >= count) continue;
            if (scene.nodes[static_cast<std::size_t>(channel.node)].hasMatrix) continue;  // glTF forbids; the loader refuses it
            Trs& p = pose[static_cast<std::size_t>(channel.node)];
            const glm::dvec4 v = sampleChannel(channel, timeSeconds);
            switch (channel.path) {
                case AnimationPath::Translation: p.translation = glm::dvec3(v); break;
                case AnimationPath::Scale: p.scale = glm::dvec3(v); break;
                case AnimationPath::Rotation: p.rotation = glm::dquat(v.w, v.x, v.y, v.z); break;
            }
        }
    }

    // Parents from the children lists (the glTF truth); composed top-down in double.
    std::vector<int> parent(count, -1);
    for (std::size_t i = 0; i < count; ++i)
        for (const int c : scene.nodes[i].children)
            if (c >= 0 && static_cast<std::size_t>(c) < count) parent[static_cast<std::size_t>(c)] = static_cast<int>(i);
    std::vector<glm::dmat4> world(count, glm::dmat4(1.0));
    std::vector<char> done(count, 0);
    std::vector<std::size_t> chain;
    for (std::size_t i = 0; i < count; ++i) {
        // Walk up to the first finished ancestor (bounded by `count` in case of a hand-made cycle).
        chain.clear();
        std::size_t n = i;
        while (!done[n] && chain.size() <= count) {
            chain.push_back(n);
            if (parent[n] < 0) break;
            n = static_cast<std::size_t>(parent[n]);
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const std::size_t k = *it;
            if (done[k]) continue;
            const Node& node = scene.nodes[k];
            const glm::dmat4 local = node.hasMatrix ? node.matrix : composeTrs(pose[k]);
            world[k] = parent[k] >= 0 && done[static_cast<std::size_t>(parent[k])] ? world[static_cast<std::size_t>(parent[k])] * local : local;
            done[k] = 1;
        }
    }
    return world;
}

Aabb meshBounds(const Scene& scene, const std::vector<glm::dmat4>& world) {
    Aabb bounds;
    const std::vector<bool> in = nodesInScene(scene);
    for (std::size_t i = 0; i < scene.nodes.size() && i < world.size(); ++i) {
        const int mesh = scene.nodes[i].mesh;
        if (!in[i] || mesh < 0 || static_cast<std::size_t>(mesh) >= scene.meshes.size()) continue;
        for (const Primitive& p : scene.meshes[static_cast<std::size_t>(mesh)].primitives) {
            for (int corner = 0; corner < 8; ++corner) {
                const glm::dvec3 local((corner & 1) ? p.boundsMax.x : p.boundsMin.x, (corner & 2) ? p.boundsMax.y : p.boundsMin.y,
                                       (corner & 4) ? p.boundsMax.z : p.boundsMin.z);
                bounds.extend(glm::dvec3(world[i] * glm::dvec4(local, 1.0)));
            }
        }
    }
    return bounds;
}

namespace {

// `text` as a camera index (decimal digits only), or −1.
int cameraIndex(std::string_view text) {
    if (text.empty() || text.size() > 9) return -1;
    int value = 0;
    for (const char c : text) {
        if (c < '0' || c > '9') return -1;
        value = value * 10 + (c - '0');
    }
    return value;
}

}  // namespace

ResolvedCamera resolveCamera(const Scene& scene, const std::vector<glm::dmat4>& world, std::string_view name,
                             const Aabb& frame, double aspect) {
    const std::vector<bool> in = nodesInScene(scene);
    const int index = cameraIndex(name);
    std::optional<ResolvedCamera> byIndex;
    std::string available;
    for (std::size_t i = 0; i < scene.nodes.size() && i < world.size(); ++i) {
        const Node& node = scene.nodes[i];
        if (!in[i] || node.camera < 0 || static_cast<std::size_t>(node.camera) >= scene.cameras.size()) continue;
        const Camera& camera = scene.cameras[static_cast<std::size_t>(node.camera)];
        ResolvedCamera out;
        out.name = !camera.name.empty() ? camera.name : !node.name.empty() ? node.name : "camera " + std::to_string(node.camera);
        out.params = camera;
        out.world = world[i];
        // A name wins over an index ("--camera 1" picks a camera named "1" before cameras[1]).
        if (name.empty() || camera.name == name || node.name == name) return out;
        if (node.camera == index && !byIndex) byIndex = out;
        const std::string label = !camera.name.empty() ? camera.name : node.name;
        available += (available.empty() ? "" : ", ") + std::to_string(node.camera) +
                     (label.empty() ? " (unnamed)" : " \"" + label + "\"");
    }
    if (byIndex) return *byIndex;
    if (!name.empty())
        throwInputError(scene.displayName(), "camera \"" + std::string(name) + "\"", "",
                        available.empty() ? "not found: the scene has no camera"
                                          : "not found; the scene's cameras (index and name) are " + available);

    // No camera: look at the centre of `frame` from (+1, +0.6, +1.4), far enough back that the
    // bounding sphere fits both the vertical and the horizontal field of view.
    ResolvedCamera out;
    out.name = "framing camera";
    out.synthesized = true;
    out.params = Camera{};
    out.params.name = out.name;
    out.params.yfov = 0.8;
    const glm::dvec3 centre = frame.empty() ? glm::dvec3(0.0) : frame.center();
    double radius = frame.empty() ? 1.0 : 0.5 * glm::length(frame.extent());
    if (!(radius > 0.0) || !std::isfinite(radius)) radius = 1.0;
    const double a = aspect > 0.0 && std::isfinite(aspect) ? aspect : 1.0;
    const double halfV = 0.5 * out.params.yfov;
    const double halfH = std::atan(std::tan(halfV) * a);
    const double distance = 1.05 * radius / std::sin(std::min(halfV, halfH));
    const glm::dvec3 direction = glm::normalize(glm::dvec3(1.0, 0.6, 1.4));
    const glm::dvec3 eye = centre + distance * direction;
    out.world = glm::inverse(glm::lookAt(eye, centre, glm::dvec3(0.0, 1.0, 0.0)));
    out.params.znear = std::max(0.5 * (distance - radius), 1e-4 * distance);
    out.params.zfar = 2.0 * (distance + radius);
    return out;
}

std::vector<ResolvedLight> resolveLights(const Scene& scene, const std::vector<glm::dmat4>& world) {
    std::vector<ResolvedLight> lights;
    const std::vector<bool> in = nodesInScene(scene);
    for (std::size_t i = 0; i < scene.nodes.size() && i < world.size(); ++i) {
        const Node& node = scene.nodes[i];
        if (!in[i] || node.light < 0 || static_cast<std::size_t>(node.light) >= scene.lights.size()) continue;
        ResolvedLight light;
        light.params = scene.lights[static_cast<std::size_t>(node.light)];
        light.name = !light.params.name.empty() ? light.params.name : node.name;
        light.position = glm::dvec3(world[i][3]);
        light.direction = unitOr(glm::dvec3(world[i] * glm::dvec4(0.0, 0.0, -1.0, 0.0)), {0.0, 0.0, -1.0});
        lights.push_back(std::move(light));
    }
    if (!lights.empty()) return lights;

    // The documented default sun (docs/scene-format.md).
    ResolvedLight sun;
    sun.name = "default sun";
    sun.params.name = sun.name;
    sun.params.type = LightType::Directional;
    sun.params.color = glm::vec3(1.0f);
    sun.params.intensity = 3.0f;
    sun.direction = glm::normalize(glm::dvec3(-0.4, -1.0, -0.3));
    sun.synthesized = true;
    lights.push_back(std::move(sun));
    return lights;
}

}  // namespace nimbus::assets
