#include "nimbus/raycast/mesh_raycaster.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <string>

#include <embree3/rtcore.h>

#include "nimbus/assets/scene_queries.h"
#include "nimbus/base/error.h"
#include "nimbus/base/log.h"

namespace nimbus::raycast {

struct MeshRaycaster::Geometry {
    int node = -1, mesh = -1, primitive = -1, material = -1;
    bool doubleSided = false;
    const assets::MaterialSampler* cutout = nullptr;  // MASK materials: alpha below alphaCutoff is no surface
    double alphaCutoff = 0.5;
    bool mirrored = false;         // negative determinant: glTF says front faces are then clockwise
    std::vector<float> vertices;   // xyz relative to the raycaster origin, + 1 float of padding (Embree reads 16 bytes)
    std::vector<std::uint32_t> indices;
    std::vector<glm::vec3> normals;  // world space, unit
    std::vector<glm::vec2> texcoords0, texcoords1;
    std::vector<glm::vec4> colors0;

    // Texture coordinates and colour at barycentrics (u, v) of a triangle (Embree: w·v0 + u·v1 + v·v2).
    assets::SurfaceAttributes attributesAt(unsigned triangle, double u, double v) const {
        const std::uint32_t i0 = indices[3 * triangle], i1 = indices[3 * triangle + 1], i2 = indices[3 * triangle + 2];
        const double w = 1.0 - u - v;
        assets::SurfaceAttributes a;
        if (!texcoords0.empty()) a.uv0 = w * glm::dvec2(texcoords0[i0]) + u * glm::dvec2(texcoords0[i1]) + v * glm::dvec2(texcoords0[i2]);
        if (!texcoords1.empty()) a.uv1 = w * glm::dvec2(texcoords1[i0]) + u * glm::dvec2(texcoords1[i1]) + v * glm::dvec2(texcoords1[i2]);
        if (!colors0.empty()) a.color = w * glm::dvec4(colors0[i0]) + u * glm::dvec4(colors0[i1]) + v * glm::dvec4(colors0[i2]);
        return a;
    }
    bool cutAway(unsigned triangle, double u, double v) const {
        return cutout != nullptr && cutout->alpha(material, attributesAt(triangle, u, v)) < alphaCutoff;
    }

    glm::dvec3 vertex(std::uint32_t i) const {
        return {vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]};
    }
    // The front-face normal (not normalised), in the raycaster's relative frame.
    glm::dvec3 frontNormal(unsigned triangle) const {
        const glm::dvec3 a = vertex(indices[3 * triangle]), b = vertex(indices[3 * triangle + 1]),
                         c = vertex(indices[3 * triangle + 2]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        return mirrored ? -n : n;
    }
};

struct MeshRaycaster::EmbreeState {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    ~EmbreeState() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

namespace {

// The intersect context carries the culling choice to the filter (Embree's documented extension
// pattern: a struct that starts with RTCIntersectContext).
struct CullingContext {
    RTCIntersectContext context;
    bool cullBackFaces = true;
};

// Back faces of single-sided materials (closest hits only, when the context asks) and alpha cutouts.
void surfaceFilter(const RTCFilterFunctionNArguments* args) {
    const auto* ctx = reinterpret_cast<const CullingContext*>(args->context);
    const auto* geometry = static_cast<const MeshRaycaster::Geometry*>(args->geometryUserPtr);
    const bool cull = ctx->cullBackFaces && !geometry->doubleSided;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned triangle = RTCHitN_primID(args->hit, args->N, i);
        if (cull) {
            const glm::dvec3 dir(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                                 RTCRayN_dir_z(args->ray, args->N, i));
            if (glm::dot(dir, geometry->frontNormal(triangle)) > 0.0) {
                args->valid[i] = 0;
                continue;
            }
        }
        if (geometry->cutAway(triangle, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i))) args->valid[i] = 0;
    }
}

void reportEmbreeError(void*, RTCError code, const char* message) {
    log::error("embree: error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : ""));
}

RTCRayHit makeRayHit(const glm::dvec3& relativeOrigin, const glm::dvec3& dir, double tNear, double tFar) {
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(relativeOrigin.x);
    rh.ray.org_y = static_cast<float>(relativeOrigin.y);
    rh.ray.org_z = static_cast<float>(relativeOrigin.z);
    rh.ray.dir_x = static_cast<float>(dir.x);
    rh.ray.dir_y = static_cast<float>(dir.y);
    rh.ray.dir_z = static_cast<float>(dir.z);
    rh.ray.tnear = static_cast<float>(std::max(0.0, tNear));
    rh.ray.tfar = tFar >= static_cast<double>(FLT_MAX) ? std::numeric_limits<float>::infinity() : static_cast<float>(tFar);
    rh.ray.mask = 0xffffffffu;
    rh.ray.flags = 0;
    rh.ray.time = 0.0f;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

}  // namespace

MeshRaycaster::MeshRaycaster(const assets::Scene& scene, const std::vector<glm::dmat4>& world)
    : embree_(std::make_unique<EmbreeState>()), materials_(std::make_unique<assets::MaterialSampler>(scene)) {
    const std::vector<bool> in = assets::nodesInScene(scene);

    // The origin: centre of the world-space vertex bounds, computed in double before any float.
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (std::size_t n = 0; n < scene.nodes.size() && n < world.size(); ++n) {
        const int mesh = scene.nodes[n].mesh;
        if (!in[n] || mesh < 0 || static_cast<std::size_t>(mesh) >= scene.meshes.size()) continue;
        for (const assets::Primitive& p : scene.meshes[static_cast<std::size_t>(mesh)].primitives)
            for (const glm::vec3& v : p.positions) {
                const glm::dvec3 w = glm::dvec3(world[n] * glm::dvec4(glm::dvec3(v), 1.0));
                lo = glm::min(lo, w);
                hi = glm::max(hi, w);
            }
    }
    if (lo.x <= hi.x) origin_ = 0.5 * (lo + hi);

    embree_->device = rtcNewDevice(nullptr);
    if (!embree_->device) throw SystemError("embree: cannot create a device (error " + std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
    rtcSetDeviceErrorFunction(embree_->device, reportEmbreeError, nullptr);
    embree_->scene = rtcNewScene(embree_->device);
    rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);

    for (std::size_t n = 0; n < scene.nodes.size() && n < world.size(); ++n) {
        const int mesh = scene.nodes[n].mesh;
        if (!in[n] || mesh < 0 || static_cast<std::size_t>(mesh) >= scene.meshes.size()) continue;
        const glm::dmat4& m = world[n];
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m)));
        const auto& primitives = scene.meshes[static_cast<std::size_t>(mesh)].primitives;
        for (std::size_t pi = 0; pi < primitives.size(); ++pi) {
            const assets::Primitive& p = primitives[pi];
            const std::size_t vertexCount = p.positions.size();
            if (p.indices.size() < 3 || vertexCount == 0) continue;
            if (std::any_of(p.indices.begin(), p.indices.end(), [&](std::uint32_t i) { return i >= vertexCount; })) {
                log::warn("raycast: a primitive of mesh " + std::to_string(mesh) + " has indices out of range; skipped");
                continue;
            }
            auto g = std::make_unique<Geometry>();
            g->node = static_cast<int>(n);
            g->mesh = mesh;
            g->primitive = static_cast<int>(pi);
            g->material = p.material;
            const assets::Material& material = materials_->material(p.material);
            g->doubleSided = material.doubleSided;
            if (material.alphaMode == assets::AlphaMode::Mask) {
                g->cutout = materials_.get();
                g->alphaCutoff = material.alphaCutoff;
            }
            g->mirrored = glm::determinant(glm::dmat3(m)) < 0.0;
            g->vertices.resize(3 * vertexCount + 1, 0.0f);
            g->normals.resize(vertexCount);
            for (std::size_t v = 0; v < vertexCount; ++v) {
                const glm::dvec3 w = glm::dvec3(m * glm::dvec4(glm::dvec3(p.positions[v]), 1.0)) - origin_;
                for (int c = 0; c < 3; ++c) g->vertices[3 * v + static_cast<std::size_t>(c)] = static_cast<float>(w[c]);
                const glm::dvec3 nrm = v < p.normals.size() ? normalMatrix * glm::dvec3(p.normals[v]) : glm::dvec3(0.0);
                const double len = glm::length(nrm);
                g->normals[v] = len > 0.0 && std::isfinite(len) ? glm::vec3(nrm / len) : glm::vec3(0.0f);
            }
            g->indices.assign(p.indices.begin(), p.indices.end() - static_cast<std::ptrdiff_t>(p.indices.size() % 3));
            if (p.texcoords0.size() == vertexCount) g->texcoords0 = p.texcoords0;
            if (p.texcoords1.size() == vertexCount) g->texcoords1 = p.texcoords1;
            if (p.colors0.size() == vertexCount) g->colors0 = p.colors0;

            RTCGeometry rg = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
            rtcSetSharedGeometryBuffer(rg, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, g->vertices.data(), 0,
                                       3 * sizeof(float), vertexCount);
            rtcSetSharedGeometryBuffer(rg, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, g->indices.data(), 0,
                                       3 * sizeof(std::uint32_t), g->indices.size() / 3);
            rtcSetGeometryUserData(rg, g.get());
            if (!g->doubleSided || g->cutout) rtcSetGeometryIntersectFilterFunction(rg, surfaceFilter);
            if (g->cutout) rtcSetGeometryOccludedFilterFunction(rg, surfaceFilter);
            rtcCommitGeometry(rg);
            const unsigned id = rtcAttachGeometry(embree_->scene, rg);
            rtcReleaseGeometry(rg);
            if (id != geometries_.size()) throw SystemError("embree: unexpected geometry id");
            triangleCount_ += g->indices.size() / 3;
            geometries_.push_back(std::move(g));
        }
    }
    rtcCommitScene(embree_->scene);
    const RTCError error = rtcGetDeviceError(embree_->device);
    if (error != RTC_ERROR_NONE) throw SystemError("embree: building the mesh scene failed (error " + std::to_string(static_cast<int>(error)) + ")");
}

MeshRaycaster::~MeshRaycaster() = default;

std::optional<MeshHit> MeshRaycaster::closestHit(const glm::dvec3& origin, const glm::dvec3& dir, double tNear,
                                                 double tFar, FaceCulling culling) const {
    if (triangleCount_ == 0 || !(tFar >= tNear)) return std::nullopt;
    CullingContext ctx;
    rtcInitIntersectContext(&ctx.context);
    ctx.cullBackFaces = culling == FaceCulling::BackOfSingleSided;
    RTCRayHit rh = makeRayHit(origin - origin_, dir, tNear, tFar);
    rtcIntersect1(embree_->scene, &ctx.context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

    const Geometry& g = *geometries_[rh.hit.geomID];
    const unsigned tri = rh.hit.primID;
    const std::uint32_t i0 = g.indices[3 * tri], i1 = g.indices[3 * tri + 1], i2 = g.indices[3 * tri + 2];
    const double u = rh.hit.u, v = rh.hit.v, w = 1.0 - u - v;  // Embree: hit = w·v0 + u·v1 + v·v2

    MeshHit hit;
    hit.distance = rh.ray.tfar;
    hit.position = origin + hit.distance * dir;
    const glm::dvec3 face = g.frontNormal(tri);
    const double faceLength = glm::length(face);
    hit.geometricNormal = faceLength > 0.0 ? face / faceLength : -dir;
    hit.backFace = glm::dot(dir, hit.geometricNormal) > 0.0;
    const glm::dvec3 shading = w * glm::dvec3(g.normals[i0]) + u * glm::dvec3(g.normals[i1]) + v * glm::dvec3(g.normals[i2]);
    const double shadingLength = glm::length(shading);
    hit.shadingNormal = shadingLength > 1e-12 ? shading / shadingLength : hit.geometricNormal;
    hit.node = g.node;
    hit.mesh = g.mesh;
    hit.primitive = g.primitive;
    hit.triangle = static_cast<int>(tri);
    hit.material = g.material;
    const assets::SurfaceAttributes at = g.attributesAt(tri, u, v);
    hit.hasTexcoord0 = !g.texcoords0.empty();
    hit.hasTexcoord1 = !g.texcoords1.empty();
    hit.texcoord0 = at.uv0;
    hit.texcoord1 = at.uv1;
    hit.color0 = at.color;
    return hit;
}

bool MeshRaycaster::occluded(const glm::dvec3& origin, const glm::dvec3& dir, double tMax) const {
    if (triangleCount_ == 0 || !(tMax > 0.0)) return false;
    CullingContext ctx;
    rtcInitIntersectContext(&ctx.context);
    ctx.cullBackFaces = false;
    RTCRayHit rh = makeRayHit(origin - origin_, dir, 0.0, tMax);
    rtcOccluded1(embree_->scene, &ctx.context, &rh.ray);
    return rh.ray.tfar == -std::numeric_limits<float>::infinity();
}

double MeshRaycaster::surfaceEpsilon(const glm::dvec3& point, double hitDistance) const {
    const glm::dvec3 local = glm::abs(point - origin_);
    const double magnitude = std::max({local.x, local.y, local.z, std::abs(hitDistance), 1e-3});
    // 64 float ulps of the largest coordinate involved: the intersection's own rounding is a few ulps.
    return 64.0 * static_cast<double>(FLT_EPSILON) * magnitude;
}

glm::dvec3 MeshRaycaster::offsetFromSurface(const MeshHit& hit, const glm::dvec3& dir) const {
    const double side = glm::dot(hit.geometricNormal, dir) >= 0.0 ? 1.0 : -1.0;
    return hit.position + side * surfaceEpsilon(hit.position, hit.distance) * hit.geometricNormal;
}

bool MeshRaycaster::occludedFromSurface(const MeshHit& hit, const glm::dvec3& dir, double distance) const {
    const double eps = surfaceEpsilon(hit.position, hit.distance);
    const double tMax = std::isinf(distance) ? distance : distance - eps;
    return occluded(offsetFromSurface(hit, dir), dir, tMax);
}

}  // namespace nimbus::raycast
