#pragma once
// The render camera of a scene as a gpu::View (the small GL part's camera, which hosts of the
// media plugin use too).
#include "nimbus/assets/scene_queries.h"
#include "nimbus/gpu/view.h"

namespace nimbus::render {

using gpu::View;
using gpu::reversedOrthographic;
using gpu::reversedPerspective;

View makeView(const assets::ResolvedCamera& camera, int width, int height);

}  // namespace nimbus::render
