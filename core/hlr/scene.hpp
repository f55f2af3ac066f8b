// What the engine draws: named solids already placed in world space.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/solid/solid.hpp"

namespace hlr {

// Solids are immutable and shared: a scene holds each in world space, and frames whose object and
// placement did not change hold the very same one (runtime/builtins/solid_cache.hpp), with its edge table and
// face planes already derived.
struct SceneObject {
  SceneObject() = default;
  SceneObject(std::string name_, std::shared_ptr<const Solid> solid_)
      : name(std::move(name_)), solid(std::move(solid_)) {}
  SceneObject(std::string name_, Solid solid_)
      : name(std::move(name_)), solid(std::make_shared<const Solid>(std::move(solid_))) {}

  std::string name;
  std::shared_ptr<const Solid> solid;  // never null
};

struct Scene {
  std::vector<SceneObject> objects;
};

}  // namespace hlr
