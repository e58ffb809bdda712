#pragma once
// A viewport point as ImGui's draw list takes it: the viewport's screen origin plus the point's
// offset in pixels, computed in double and narrowed once.
#include <glm/glm.hpp>
#include <imgui.h>

namespace nimbus::sandbox::editor {

inline ImVec2 toImVec(glm::dvec2 origin, glm::dvec2 p) {
    return ImVec2(static_cast<float>(origin.x + p.x), static_cast<float>(origin.y + p.y));
}

}  // namespace nimbus::sandbox::editor
