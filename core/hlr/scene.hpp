// What the engine draws: named solids already placed in world space.
#pragma once

#include <string>
#include <vector>

#include "core/solid/solid.hpp"

namespace hlr {

struct SceneObject {
  std::string name;
  Solid solid;
};

struct Scene {
  std::vector<SceneObject> objects;
};

}  // namespace hlr
