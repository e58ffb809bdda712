#include "nimbus/gpu/frame_layout.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "nimbus/base/error.h"

namespace nimbus::gpu {

GpuFrame packFrame(const View& view, const glm::vec3& ambient, const glm::vec3& background, int lights, int shadowMapSize,
                   int pcfRadius, const FogParams& fog) {
    GpuFrame f{};
    f.viewProjection = view.viewProjection;
    f.view = view.view;
    f.inverseViewProjection = view.inverseViewProjection;
    const bool ortho = view.orthographic;
    f.cameraRight = glm::vec4(glm::vec3(view.right), ortho ? view.orthoHalfExtent.x : view.tanHalfFovY * view.aspect);
    f.cameraUp = glm::vec4(glm::vec3(view.up), ortho ? view.orthoHalfExtent.y : view.tanHalfFovY);
    f.cameraForward = glm::vec4(glm::vec3(view.forward), ortho ? 1.0f : 0.0f);
    f.depthParams = glm::vec4(view.depthLinearization(), view.znear, view.zfar);
    f.viewport = glm::vec4(static_cast<float>(view.width), static_cast<float>(view.height), 1.0f / static_cast<float>(view.width),
                           1.0f / static_cast<float>(view.height));
    f.ambient = glm::vec4(ambient, 0.0f);
    f.background = glm::vec4(background, 0.0f);
    f.counts = glm::ivec4(lights, 0, shadowMapSize, pcfRadius);
    f.fogColor = glm::vec4(fog.color, static_cast<float>(fog.kind));
    f.fogParams = glm::vec4(fog.density, fog.start, fog.end, fog.falloff);
    // The height is taken in double before the float: frames far from the world origin keep it exact.
    const double fogReach = fog.backgroundDistance > 0.0 ? std::min(fog.backgroundDistance, 1e30) : 1e30;
    f.fogHeight = glm::vec4(static_cast<float>(view.origin.y - fog.base), static_cast<float>(fogReach), 0.0f, 0.0f);
    return f;
}

GpuLight packLight(const PunctualLight& l, const glm::dvec3& origin, int firstShadowView, int shadowViews) {
    GpuLight g{};
    g.position = glm::vec4(glm::vec3(l.position - origin), static_cast<float>(l.range));
    const float type = l.kind == LightKind::Directional ? 0.0f : l.kind == LightKind::Point ? 1.0f : 2.0f;
    g.direction = glm::vec4(glm::vec3(l.direction), type);
    g.radiance = glm::vec4(l.radiance, 0.0f);
    const double cosInner = std::cos(l.innerConeAngle), cosOuter = std::cos(l.outerConeAngle);
    const double scale = 1.0 / std::max(0.001, cosInner - cosOuter);
    g.spot = glm::vec4(static_cast<float>(scale), static_cast<float>(-cosOuter * scale),
                       firstShadowView < 0 ? -1.0f : static_cast<float>(firstShadowView), static_cast<float>(shadowViews));
    return g;
}

GpuLightView packLightView(const LightView& v, int firstLayer, float sliceCount, float texels) {
    GpuLightView g{};
    g.view = v.view;
    g.viewProjection = v.viewProjection;
    g.params = glm::vec4(v.perspective ? 1.0f : 0.0f, v.depthNear, v.depthFar, sliceCount);
    // World size of one texel: at depth 1 for perspective views (scale by depth in the shader).
    const float texelSize = 2.0f * v.halfExtent.x / std::max(texels, 1.0f);
    g.params2 = glm::vec4(static_cast<float>(firstLayer), texelSize, v.halfExtent.x, v.halfExtent.y);
    return g;
}

int shadowViewSide(LightKind kind, int shadowMapSize, int pointFaceSize) {
    return kind == LightKind::Point && pointFaceSize > 0 ? std::min(pointFaceSize, shadowMapSize) : shadowMapSize;
}

PackedLights packLights(const std::vector<PunctualLight>& lights, const glm::dvec3& origin,
                        const std::vector<std::vector<LightView>>& shadowViews, int shadowMapSize, int pointFaceSize) {
    PackedLights out;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const std::size_t views = i < shadowViews.size() ? shadowViews[i].size() : 0;
        const int first = views == 0 ? -1 : static_cast<int>(out.shadowViews.size());
        out.lights.push_back(packLight(lights[i], origin, first, static_cast<int>(views)));
        const int side = shadowViewSide(lights[i].kind, shadowMapSize, pointFaceSize);
        const float share = shadowMapSize > 0 ? static_cast<float>(side) / static_cast<float>(shadowMapSize) : 1.0f;
        for (std::size_t v = 0; v < views; ++v)
            out.shadowViews.push_back(
                packLightView(shadowViews[i][v], static_cast<int>(out.shadowViews.size()), share, static_cast<float>(side)));
    }
    return out;
}

void uploadBlock(GLuint buffer, std::size_t capacity, const void* items, std::size_t count, std::size_t itemSize, const char* what) {
    if (count > capacity)
        throw InputError(std::to_string(count) + " " + what + " in one frame; the real-time renderer draws at most " + std::to_string(capacity));
    if (count > 0) glNamedBufferSubData(buffer, 0, static_cast<GLsizeiptr>(count * itemSize), items);
}

}  // namespace nimbus::gpu
