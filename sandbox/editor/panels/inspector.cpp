// The inspector: typed widgets for what users tune most (transform, medium, emitter preset, light,
// camera, material colour, environment), then every other field of the node as a tree, so nothing
// in the file is out of reach. Ranges and enums are the loader's: a bad value is refused with its message.
#include <imgui.h>

#include <glm/gtc/quaternion.hpp>

#include "nimbus/assets/scene.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/scene/components.h"
#include "panels.h"

namespace nimbus::sandbox::editor {
namespace {

const std::string kMedia = std::string("extensions.") + assets::kMediaExtension;

void particleSummary(EditorState& state, int node) {
    namespace mecs = media::ecs;
    auto& world = state.session().app().world();
    std::size_t cloud = 0, alive = 0;
    world.view<scene::SceneNode, mecs::MediumComponent>().each(
        [&](ecs::Entity entity, const scene::SceneNode& n, const mecs::MediumComponent&) {
            if (n.node != node) return;
            if (const auto* c = world.tryGet<mecs::ParticleCloud>(entity)) cloud += c->positions.size();
            if (const auto* e = world.tryGet<mecs::EmitterComponent>(entity)) alive += e->simulation.particles().size();
        });
    ImGui::Text("particles: %zu static, %zu alive from the emitter at t = %.2f s", cloud, alive, state.time());
}

void mediumSection(EditorState& state, FieldWidgets& f, int node) {
    if (getField(state.json(), node, kMedia).is_null() || !ImGui::CollapsingHeader("Medium", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const std::string m = kMedia + ".medium";
    f.number("extinction (1/m)", node, m + ".extinction", 1.0, 0.05f);
    f.colour("albedo", node, m + ".albedo", {1.0, 1.0, 1.0}, false);
    f.number("g", node, m + ".g", 0.0, 0.01f);
    f.colour("emission", node, m + ".emission", {0.0, 0.0, 0.0}, true);
    f.choice("phase", node, m + ".phase", {"henyey-greenstein", "rayleigh"}, "henyey-greenstein");
    if (!getField(state.json(), node, kMedia + ".emitter").is_null()) {
        ImGui::Separator();
        ImGui::TextUnformatted("Emitter");
        f.choice("preset", node, kMedia + ".emitter.preset", {"smoke", "steam", "vapor_trail", "fire", "explosion"}, "", true);
        f.tree("emitter fields", node, kMedia + ".emitter");
    }
    if (!getField(state.json(), node, kMedia + ".particles").is_null()) f.tree("particles (accessors)", node, kMedia + ".particles");
    f.tree("render overrides", node, kMedia + ".render");
    particleSummary(state, node);
}

void transformSection(EditorState& state, FieldWidgets& f, int node) {
    if (!ImGui::CollapsingHeader("Transform", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (!getField(state.json(), node, "matrix").is_null()) {
        ImGui::TextWrapped("Given as a matrix; moving it with the gizmo converts it to translation/rotation/scale.");
        f.tree("matrix", node, "matrix");
        return;
    }
    f.vector("translation", node, "translation", 3, {0.0, 0.0, 0.0});
    f.vector("rotation (x y z w)", node, "rotation", 4, {0.0, 0.0, 0.0, 1.0}, 0.005f);
    f.vector("scale", node, "scale", 3, {1.0, 1.0, 1.0});
}

void lightSection(EditorState& state, FieldWidgets& f, int node) {
    const Json index = getField(state.json(), node, "extensions.KHR_lights_punctual.light");
    if (!index.is_number_integer() || !ImGui::CollapsingHeader("Light", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const std::string l = "extensions.KHR_lights_punctual.lights." + std::to_string(index.get<int>());
    f.choice("type", -1, l + ".type", {"directional", "point", "spot"}, "point");
    f.colour("colour", -1, l + ".color", {1.0, 1.0, 1.0}, false);
    f.number("intensity", -1, l + ".intensity", 1.0, 0.1f);
    f.number("range (0: none)", -1, l + ".range", 0.0, 0.1f);
    if (getField(state.json(), -1, l + ".type") == "spot") {
        f.number("inner cone", -1, l + ".spot.innerConeAngle", 0.0);
        f.number("outer cone", -1, l + ".spot.outerConeAngle", 0.7853981633974483);
    }
}

void cameraSection(EditorState& state, FieldWidgets& f, int node) {
    const Json index = getField(state.json(), node, "camera");
    if (!index.is_number_integer() || !ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) return;
    f.tree("camera", -1, "cameras." + std::to_string(index.get<int>()));
}

void materialSection(EditorState& state, FieldWidgets& f, int node) {
    const Json mesh = getField(state.json(), node, "mesh");
    if (!mesh.is_number_integer() || !ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const Json primitives = getField(state.json(), -1, "meshes." + std::to_string(mesh.get<int>()) + ".primitives");
    std::vector<int> seen;
    for (const Json& p : primitives) {
        if (!p.contains("material") || std::find(seen.begin(), seen.end(), p["material"].get<int>()) != seen.end()) continue;
        const int material = p["material"].get<int>();
        seen.push_back(material);
        // The glTF factors (docs/scene-format.md §4.1), at glTF's defaults when the file omits them.
        const std::string base = "materials." + std::to_string(material) + ".";
        const std::string label = " of material " + std::to_string(material);
        ImGui::PushID(material);
        f.vector(("base colour" + label).c_str(), -1, base + "pbrMetallicRoughness.baseColorFactor", 4, {1.0, 1.0, 1.0, 1.0}, 0.005f);
        f.number(("metallic" + label).c_str(), -1, base + "pbrMetallicRoughness.metallicFactor", 1.0, 0.005f);
        f.number(("roughness" + label).c_str(), -1, base + "pbrMetallicRoughness.roughnessFactor", 1.0, 0.005f);
        f.colour(("emissive" + label).c_str(), -1, base + "emissiveFactor", {0.0, 0.0, 0.0}, true);
        ImGui::PopID();
    }
    if (seen.empty()) ImGui::TextDisabled("the glTF default material (add one to the file to tune it)");
}

void environmentSection(EditorState& state, FieldWidgets& f) {
    ImGui::TextUnformatted("Scene environment");
    f.colour("background", -1, kMedia + ".background", {0.0, 0.0, 0.0}, true);
    f.colour("ambient", -1, kMedia + ".ambient", {0.0, 0.0, 0.0}, true);
    // The optical model: every mode and the reference snapshot follow it (docs/scene-format.md).
    f.choice("scattering", -1, kMedia + ".scattering", {"multiple", "single"}, "multiple");
    if (getField(state.json(), -1, kMedia + ".fog").is_null()) {
        if (ImGui::Button("Add fog"))
            f.commit(-1, kMedia + ".fog", {{"mode", "exp"}, {"density", 0.02}, {"color", {0.6, 0.65, 0.7}}});
        return;
    }
    f.choice("fog mode", -1, kMedia + ".fog.mode", {"exp", "exp2", "linear", "height"}, "exp");
    f.colour("fog colour", -1, kMedia + ".fog.color", {0.0, 0.0, 0.0}, true);
    f.tree("fog", -1, kMedia + ".fog");
    if (ImGui::Button("Remove fog")) f.commit(-1, kMedia + ".fog", nullptr);
}

}  // namespace

void drawInspector(EditorState& state, FieldWidgets& f) {
    const int node = state.selected();
    if (node < 0) {
        environmentSection(state, f);
        return;
    }
    ImGui::PushID(node);
    f.text("name", node, "name");
    transformSection(state, f, node);
    mediumSection(state, f, node);
    lightSection(state, f, node);
    cameraSection(state, f, node);
    materialSection(state, f, node);
    if (ImGui::CollapsingHeader("All fields")) f.tree("node", node, "");
    ImGui::PopID();
}

}  // namespace nimbus::sandbox::editor
