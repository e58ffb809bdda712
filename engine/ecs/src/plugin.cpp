#include "nimbus/ecs/plugin.h"

namespace nimbus::ecs {

Plugin::~Plugin() = default;  // out of line: anchors the vtable in this library

}  // namespace nimbus::ecs
