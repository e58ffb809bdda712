#include "animation.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace mini {
namespace {

glm::dvec4 unitQuaternion(const glm::dvec4& q) {
    const double length = glm::length(q);
    return length > 1e-300 && std::isfinite(length) ? q / length : glm::dvec4(0.0, 0.0, 0.0, 1.0);
}

glm::dvec4 slerp(const glm::dvec4& a, const glm::dvec4& b, double s) {
    const glm::dvec4 qa = unitQuaternion(a);
    glm::dvec4 qb = unitQuaternion(b);
    double cosine = glm::dot(qa, qb);
    if (cosine < 0.0) {  // q and −q are one rotation: go the short way
        qb = -qb;
        cosine = -cosine;
    }
    if (cosine > 0.9995) return unitQuaternion(glm::mix(qa, qb, s));  // acos is ill-conditioned near 1
    const double angle = std::acos(std::min(cosine, 1.0));
    return unitQuaternion((std::sin((1.0 - s) * angle) * qa + std::sin(s * angle) * qb) / std::sin(angle));
}

// Hermite spline between keys k and k+1 (glTF Appendix C); tangents scaled by the key interval.
glm::dvec4 cubic(const Channel& c, std::size_t k, double s, double dt) {
    const glm::dvec4 p0(c.values[3 * k + 1]), m0 = dt * glm::dvec4(c.values[3 * k + 2]);
    const glm::dvec4 p1(c.values[3 * k + 4]), m1 = dt * glm::dvec4(c.values[3 * k + 3]);
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
}

}  // namespace

glm::dvec4 sampleChannel(const Channel& channel, double t) {
    const bool rotation = channel.path == AnimationPath::Rotation;
    const bool spline = channel.interpolation == Interpolation::CubicSpline;
    const std::size_t keys = channel.times.size();
    auto key = [&](std::size_t k) { return glm::dvec4(channel.values[spline ? 3 * k + 1 : k]); };
    auto result = [&](const glm::dvec4& v) { return rotation ? unitQuaternion(v) : glm::dvec4(glm::dvec3(v), 0.0); };
    if (keys == 0) return rotation ? glm::dvec4(0, 0, 0, 1) : glm::dvec4(channel.path == AnimationPath::Scale ? 1.0 : 0.0);

    if (!(t > channel.times.front())) return result(key(0));  // before the first key (or NaN)
    if (t >= channel.times.back()) return result(key(keys - 1));
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(channel.times.begin(), channel.times.end(), t) - channel.times.begin()) - 1;
    const double t0 = channel.times[k], dt = channel.times[k + 1] - t0;
    const double s = (t - t0) / dt;
    switch (channel.interpolation) {
        case Interpolation::Step: return result(key(k));
        case Interpolation::CubicSpline: return result(cubic(channel, k, s, dt));
        case Interpolation::Linear: break;
    }
    return rotation ? slerp(key(k), key(k + 1), s) : result(glm::mix(key(k), key(k + 1), s));
}

void applyChannel(const Channel& channel, const glm::dvec4& v, Pose& pose) {
    switch (channel.path) {
        case AnimationPath::Translation: pose.translation = glm::dvec3(v); break;
        case AnimationPath::Scale: pose.scale = glm::dvec3(v); break;
        case AnimationPath::Rotation: pose.rotation = glm::dquat(v.w, v.x, v.y, v.z); break;
    }
}

glm::dmat4 poseMatrix(const Pose& pose) {
    const glm::dmat4 translation = glm::translate(glm::dmat4(1.0), pose.translation);
    return glm::scale(translation * glm::mat4_cast(pose.rotation), pose.scale);
}

std::vector<glm::dmat4> worldTransformsAt(const Scene& scene, double time) {
    std::vector<Pose> poses;
    for (const Node& node : scene.nodes) poses.push_back(node.pose);
    for (const Channel& channel : scene.channels)
        if (channel.node >= 0 && static_cast<std::size_t>(channel.node) < poses.size() && !scene.nodes[static_cast<std::size_t>(channel.node)].hasMatrix)
            applyChannel(channel, sampleChannel(channel, time), poses[static_cast<std::size_t>(channel.node)]);
    std::vector<glm::dmat4> world(scene.nodes.size());
    std::vector<char> done(scene.nodes.size(), 0);
    // Parents first: walk each node's chain up to a finished ancestor (bounded against cycles).
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        std::vector<std::size_t> chain;
        for (std::size_t n = i; !done[n] && chain.size() <= scene.nodes.size();) {
            chain.push_back(n);
            if (scene.nodes[n].parent < 0) break;
            n = static_cast<std::size_t>(scene.nodes[n].parent);
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const Node& node = scene.nodes[*it];
            const glm::dmat4 local = node.hasMatrix ? node.matrix : poseMatrix(poses[*it]);
            const bool parentDone = node.parent >= 0 && done[static_cast<std::size_t>(node.parent)];
            world[*it] = parentDone ? world[static_cast<std::size_t>(node.parent)] * local : local;
            done[*it] = 1;
        }
    }
    return world;
}

}  // namespace mini
