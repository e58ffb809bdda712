#include "gltf_animation_builder.h"

#include <cmath>

#include "gltf_accessor.h"
#include "json_fields.h"
#include "nimbus/base/log.h"

namespace nimbus::assets {
namespace {

Interpolation interpolationFromString(const std::string& s) {
    if (s == "STEP") return Interpolation::Step;
    if (s == "CUBICSPLINE") return Interpolation::CubicSpline;
    return Interpolation::Linear;
}

std::vector<float> readKeyTimes(const tinygltf::Model& model, int accessor, const std::string& file, const JsonPlace& place,
                                const std::string& field) {
    std::vector<float> times = readAccessorFloats(model, accessor, file);
    for (std::size_t k = 0; k < times.size(); ++k) {
        if (!std::isfinite(times[k])) place.fail(field, "key time " + std::to_string(k) + " is not finite");
        if (k > 0 && !(times[k] > times[k - 1]))
            place.fail(field, "key times must strictly increase (key " + std::to_string(k) + ": " + Json(times[k]).dump() +
                                  " after " + Json(times[k - 1]).dump() + ")");
    }
    return times;
}

std::vector<glm::vec4> readKeyValues(const tinygltf::Model& model, int accessor, AnimationPath path, Interpolation interpolation,
                                     const std::string& file, const JsonPlace& place, const std::string& field) {
    const std::vector<float> flat = readAccessorFloats(model, accessor, file);
    const std::size_t n = path == AnimationPath::Rotation ? 4 : 3;
    std::vector<glm::vec4> values(flat.size() / n, glm::vec4(0.0f));
    for (std::size_t i = 0; i < values.size(); ++i) {
        for (std::size_t c = 0; c < n; ++c) {
            const float v = flat[i * n + c];
            if (!std::isfinite(v)) place.fail(field, "value " + std::to_string(i) + " is not finite");
            values[i][static_cast<int>(c)] = v;
        }
        // A rotation key (not a cubic tangent) must be a usable quaternion; sampling normalizes it.
        const bool isKeyValue = interpolation != Interpolation::CubicSpline || i % 3 == 1;
        if (path == AnimationPath::Rotation && isKeyValue && !(glm::length(values[i]) > 1e-6f))
            place.fail(field, "rotation value " + std::to_string(i) + " is a zero quaternion");
    }
    return values;
}

}  // namespace

std::vector<Animation> buildAnimations(const tinygltf::Model& model, const nlohmann::json& root, const std::string& file) {
    std::vector<Animation> animations;
    const auto it = root.find("animations");
    if (it == root.end()) return animations;
    for (std::size_t a = 0; a < it->size(); ++a) {
        const Json& src = (*it)[a];
        const JsonPlace place{&file, describeObject("animation", "animations", a, src), ""};
        Animation anim;
        anim.name = src.value("name", "");
        const Json& samplers = src["samplers"];
        const Json& channels = src["channels"];
        for (std::size_t c = 0; c < channels.size(); ++c) {
            const Json& channel = channels[c];
            const Json& target = channel["target"];
            const std::string path = target["path"].get<std::string>();
            if (!target.contains("node")) continue;  // glTF: a channel without a node is ignored
            if (path == "weights") {
                log::warn(file + ": " + place.object + ": channels[" + std::to_string(c) +
                          "]: morph target weights are not animated by Nimbus; channel ignored");
                continue;
            }
            const std::size_t s = channel["sampler"].get<std::size_t>();
            const Json& sampler = samplers[s];
            const std::string prefix = "samplers[" + std::to_string(s) + "].";
            AnimationChannel out;
            out.node = target["node"].get<int>();
            out.path = path == "translation" ? AnimationPath::Translation
                       : path == "rotation"  ? AnimationPath::Rotation
                                             : AnimationPath::Scale;
            out.interpolation = interpolationFromString(sampler.value("interpolation", "LINEAR"));
            out.times = readKeyTimes(model, sampler["input"].get<int>(), file, place, prefix + "input");
            out.values = readKeyValues(model, sampler["output"].get<int>(), out.path, out.interpolation, file, place,
                                       prefix + "output");
            anim.channels.push_back(std::move(out));
        }
        animations.push_back(std::move(anim));
    }
    return animations;
}

}  // namespace nimbus::assets
