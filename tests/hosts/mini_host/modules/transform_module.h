#pragma once
// Scene, animation and transforms:
//   OnLoad   scene.spawn          loads SceneRequest::file once; one entity per glTF node
//   OnUpdate animation.sample     rest pose, then every channel at SceneRequest::time
//   OnUpdate transform.propagate  WorldTransform = parent's WorldTransform × local, in double
#include "modules/components.h"

namespace mini {

struct TransformModule {
    static void import(ecs::World& world);
};

}  // namespace mini
