#pragma once
// `billboards`: the yardstick a typical engine ships (lit sprites, no volumetric shadows), a
// measured baseline for `sandbox bench`, not a feature to tune.
#include "nimbus/media/technique.h"

namespace nimbus::media {

TechniqueEntry billboardsTechnique();

}  // namespace nimbus::media
