#pragma once
// Test helper: scenes built in memory (no file), for the raycaster and the reference renderer.
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "nimbus/assets/scene.h"
#include "nimbus/assets/scene_queries.h"

namespace nimbus::fixtures {

// A parallelogram corner, corner+u, corner+u+v, corner+v as two counter-clockwise triangles seen
// from the side cross(u, v) points to. Texcoords: (0,0) at the corner, (1,1) opposite.
inline assets::Primitive quad(const glm::vec3& corner, const glm::vec3& u, const glm::vec3& v, int material = -1) {
    assets::Primitive p;
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    p.positions = {corner, corner + u, corner + u + v, corner + v};
    p.normals = {n, n, n, n};
    p.texcoords0 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    p.indices = {0, 1, 2, 0, 2, 3};
    p.material = material;
    p.boundsMin = glm::min(glm::min(p.positions[0], p.positions[1]), glm::min(p.positions[2], p.positions[3]));
    p.boundsMax = glm::max(glm::max(p.positions[0], p.positions[1]), glm::max(p.positions[2], p.positions[3]));
    return p;
}

// An axis-aligned box with outward faces (flat normals), as one primitive.
inline assets::Primitive box(const glm::vec3& lo, const glm::vec3& hi, int material = -1) {
    assets::Primitive out;
    const glm::vec3 d = hi - lo;
    const assets::Primitive faces[6] = {
        quad({lo.x, lo.y, lo.z}, {0, 0, d.z}, {0, d.y, 0}, material),  // -X
        quad({hi.x, lo.y, lo.z}, {0, d.y, 0}, {0, 0, d.z}, material),  // +X
        quad({lo.x, lo.y, lo.z}, {d.x, 0, 0}, {0, 0, d.z}, material),  // -Y
        quad({lo.x, hi.y, lo.z}, {0, 0, d.z}, {d.x, 0, 0}, material),  // +Y
        quad({lo.x, lo.y, lo.z}, {0, d.y, 0}, {d.x, 0, 0}, material),  // -Z
        quad({lo.x, lo.y, hi.z}, {d.x, 0, 0}, {0, d.y, 0}, material),  // +Z
    };
    for (const assets::Primitive& f : faces) {
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        out.positions.insert(out.positions.end(), f.positions.begin(), f.positions.end());
        out.normals.insert(out.normals.end(), f.normals.begin(), f.normals.end());
        for (std::uint32_t i : f.indices) out.indices.push_back(base + i);
    }
    out.material = material;
    out.boundsMin = lo;
    out.boundsMax = hi;
    return out;
}

// A UV sphere: `columns` × `rows` quads, counter-clockwise seen from outside, vertex normals the
// exact sphere normals (interpolated across a triangle they stay within O(h²) of it, h = π/rows).
inline assets::Primitive sphere(const glm::vec3& centre, float radius, int columns, int rows, int material = -1) {
    assets::Primitive p;
    const double pi = 3.14159265358979323846;
    for (int r = 0; r <= rows; ++r)
        for (int c = 0; c <= columns; ++c) {
            const double theta = pi * r / rows, phi = 2.0 * pi * c / columns;
            const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
            p.normals.push_back(glm::vec3(n));
            p.positions.push_back(centre + radius * glm::vec3(n));
            p.texcoords0.push_back(glm::vec2(float(c) / columns, float(r) / rows));
        }
    const auto at = [&](int r, int c) { return static_cast<std::uint32_t>(r * (columns + 1) + c); };
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            if (r > 0) p.indices.insert(p.indices.end(), {at(r, c), at(r + 1, c), at(r, c + 1)});
            if (r + 1 < rows) p.indices.insert(p.indices.end(), {at(r, c + 1), at(r + 1, c), at(r + 1, c + 1)});
        }
    p.material = material;
    p.boundsMin = centre - glm::vec3(radius);
    p.boundsMax = centre + glm::vec3(radius);
    return p;
}

class SceneBuilder {
public:
    assets::Scene scene;

    // A rough dielectric (metallic 0, roughness 1: glTF's closest to Lambert) unless `metallic`.
    int addMaterial(const glm::vec3& color, bool doubleSided = false, float metallic = 0.0f) {
        assets::Material m;
        m.baseColorFactor = glm::vec4(color, 1.0f);
        m.doubleSided = doubleSided;
        m.metallicFactor = metallic;
        scene.materials.push_back(m);
        return static_cast<int>(scene.materials.size()) - 1;
    }

    // A root node carrying one mesh with the given primitives.
    int addMesh(std::vector<assets::Primitive> primitives, const glm::dvec3& translation = glm::dvec3(0.0)) {
        assets::Mesh mesh;
        mesh.primitives = std::move(primitives);
        scene.meshes.push_back(std::move(mesh));
        assets::Node node;
        node.mesh = static_cast<int>(scene.meshes.size()) - 1;
        node.translation = translation;
        return addNode(node);
    }

    int addNode(const assets::Node& node) {
        scene.nodes.push_back(node);
        const int index = static_cast<int>(scene.nodes.size()) - 1;
        scene.rootNodes.push_back(index);
        return index;
    }

    std::vector<glm::dmat4> world() const { return assets::computeWorldTransforms(scene, 0.0); }
};

// A camera at `eye` looking at `target` (+Y up unless `up` says otherwise).
inline assets::ResolvedCamera lookAt(const glm::dvec3& eye, const glm::dvec3& target, double yfov = 0.8,
                                     const glm::dvec3& up = {0.0, 1.0, 0.0}) {
    assets::ResolvedCamera c;
    c.name = "test camera";
    c.params.yfov = yfov;
    c.params.znear = 0.01;
    c.params.zfar = 0.0;
    c.world = glm::inverse(glm::lookAt(eye, target, up));
    return c;
}

inline assets::ResolvedCamera orthographic(const glm::dvec3& eye, const glm::dvec3& target, double xmag, double ymag,
                                           const glm::dvec3& up = {0.0, 1.0, 0.0}) {
    assets::ResolvedCamera c = lookAt(eye, target, 0.8, up);
    c.params.projection = assets::Projection::Orthographic;
    c.params.xmag = xmag;
    c.params.ymag = ymag;
    return c;
}

inline assets::ResolvedLight sun(const glm::dvec3& travelDirection, float lux, const glm::vec3& color = glm::vec3(1.0f)) {
    assets::ResolvedLight l;
    l.name = "sun";
    l.params.type = assets::LightType::Directional;
    l.params.intensity = lux;
    l.params.color = color;
    l.direction = glm::normalize(travelDirection);
    return l;
}

}  // namespace nimbus::fixtures
