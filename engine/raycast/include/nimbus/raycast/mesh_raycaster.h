#pragma once
// CPU ray queries against a scene's opaque meshes (Embree 3): closest hit for camera rays and
// occlusion for shadow rays. The reference renderer's mesh visibility comes from here.
//
// Precision: every triangle is stored in world space RELATIVE TO origin() (the centre of the mesh
// bounds) in float; rays are given in double world space and translated before the conversion, so a
// scene 1e5 m from the world origin is as exact as one at the origin.
//
// Faces: glTF triangles are counter-clockwise seen from the front. Closest-hit queries skip the back
// faces of single-sided materials by default (the rasteriser culls them); occlusion queries are
// blocked by every face.
//
// Alpha cutouts: a triangle of a MASK material is no surface where its base colour's alpha
// (assets/material_sampling.h) is below alphaCutoff, for closest hits and occlusion alike (an
// Embree filter function), as the rasteriser discards those fragments and shadow-map texels.
//
// Does not: shade, animate (rebuild it for another time), or intersect anything but triangles.
// Queries are const and thread-safe.
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/assets/material_sampling.h"
#include "nimbus/assets/scene.h"

namespace nimbus::raycast {

struct MeshHit {
    double distance = 0.0;         // along the (unit) query direction
    glm::dvec3 position{0.0};      // origin + distance · dir, world space
    glm::dvec3 shadingNormal{0.0, 1.0, 0.0};    // unit: vertex normals interpolated, via the inverse transpose
    glm::dvec3 geometricNormal{0.0, 1.0, 0.0};  // unit: the face's counter-clockwise normal in world space
    bool backFace = false;         // the ray hit the face from behind (dot(dir, geometricNormal) > 0)
    int node = -1;                 // scene node carrying the mesh
    int mesh = -1;
    int primitive = -1;            // index in the mesh's primitives
    int triangle = -1;
    int material = -1;             // -1: the glTF default material
    bool hasTexcoord0 = false, hasTexcoord1 = false;
    glm::dvec2 texcoord0{0.0}, texcoord1{0.0};
    glm::dvec4 color0{1.0};        // COLOR_0 interpolated, 1 when the primitive has none

    // What material_sampling.h evaluates the material with (absent sets read as (0, 0)).
    assets::SurfaceAttributes attributes() const { return {texcoord0, texcoord1, color0}; }
};

enum class FaceCulling {
    BackOfSingleSided,  // like the rasteriser: back faces of single-sided materials are invisible
    None,               // every face counts
};

class MeshRaycaster {
public:
    // Every mesh instance of the scene's node hierarchy (nodes reachable from scene.rootNodes), at
    // the given world transforms (computeWorldTransforms). Throws nimbus::SystemError when Embree fails.
    MeshRaycaster(const assets::Scene& scene, const std::vector<glm::dmat4>& world);
    ~MeshRaycaster();
    MeshRaycaster(const MeshRaycaster&) = delete;
    MeshRaycaster& operator=(const MeshRaycaster&) = delete;

    bool empty() const { return triangleCount_ == 0; }
    std::size_t triangleCount() const { return triangleCount_; }
    glm::dvec3 origin() const { return origin_; }

    // The first hit along origin + t·dir with t in [tNear, tFar] (dir unit length; tFar may be +inf).
    std::optional<MeshHit> closestHit(const glm::dvec3& origin, const glm::dvec3& dir, double tNear, double tFar,
                                      FaceCulling culling = FaceCulling::BackOfSingleSided) const;

    // Whether any face blocks origin + t·dir for t in (0, tMax) (tMax may be +inf).
    bool occluded(const glm::dvec3& origin, const glm::dvec3& dir, double tMax) const;

    // How far a secondary ray leaving a surface point must start to miss its own triangle: grows with
    // the point's distance from origin() and along the ray that found it (float precision there).
    double surfaceEpsilon(const glm::dvec3& point, double hitDistance) const;

    // A start point for a ray leaving `hit` towards `dir`: moved off the surface along the geometric
    // normal, to the side `dir` points to.
    glm::dvec3 offsetFromSurface(const MeshHit& hit, const glm::dvec3& dir) const;

    // Occlusion of the segment from a surface point towards dir, up to `distance` (light distance).
    bool occludedFromSurface(const MeshHit& hit, const glm::dvec3& dir, double distance) const;

    struct Geometry;  // one (node, primitive) instance; internal

private:
    struct EmbreeState;
    std::unique_ptr<EmbreeState> embree_;
    std::unique_ptr<assets::MaterialSampler> materials_;  // alpha cutouts
    std::vector<std::unique_ptr<Geometry>> geometries_;
    glm::dvec3 origin_{0.0};
    std::size_t triangleCount_ = 0;
};

}  // namespace nimbus::raycast
