// Solids that do not change from frame to frame are made once. A generator called with the same
// arguments (torus(3, 1.2, major: 250)) returns the same immutable solid in every frame, and a draw that
// places the same solid by the same transform returns the same world-space solid, its edge table and
// face planes derived once; frames hold them by shared pointer, as ln's TransformedShape holds a shape.
// Keys are exact (argument bits, the transform's bits), so a cached solid is the one the call would
// make. The cache is shared by every frame and thread of the process and bounded by the faces it holds
// (least recently used first out), so a long sequence whose solids do change keeps memory flat.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/affine3.hpp"
#include "core/solid/solid.hpp"
#include "runtime/values/arguments.hpp"

namespace hlr::runtime {

struct SolidCacheStats {
  std::size_t hits = 0, misses = 0, faces = 0, entries = 0;
};

class SolidCache {
 public:
  using Make = std::function<std::shared_ptr<const Solid>()>;

  explicit SolidCache(std::size_t max_faces);
  ~SolidCache();
  SolidCache(const SolidCache&) = delete;
  SolidCache& operator=(const SolidCache&) = delete;

  // The solid of the generator whose signature is `function` for these arguments: the cached one, else
  // make()'s (kept when the arguments can be keyed: numbers, booleans, strings, vectors, lists and ranges of
  // them).
  std::shared_ptr<const Solid> generated(const std::string& function, const std::vector<Arg>& args,
                                         const Make& make);
  // `source` moved by `world_from_object`: the cached one, else make()'s.
  std::shared_ptr<const Solid> placed(const std::shared_ptr<const Solid>& source,
                                      const Affine3& world_from_object, const Make& make);

  // What `make` derives from `source` (hatch() lays lines on it), `how` the exact key of the derivation: the
  // cached one, else make()'s.
  std::shared_ptr<const Solid> derived(const std::shared_ptr<const Solid>& source, const std::string& how,
                                       const Make& make);
  SolidCacheStats stats() const;
  void clear();

  // The process's cache (frames and the REPL share it); about 2 million faces.
  static SolidCache& shared();

 private:
  struct State;
  std::shared_ptr<const Solid> lookup_or_make(const std::string& key,
                                              const std::shared_ptr<const Solid>& source, const Make& make);
  std::unique_ptr<State> s_;
};

// Appends the bits of x to a cache key (exact: no two doubles give the same bytes).
void put_bits(double x, std::string& out);

// The exact text key of a value, or nullopt when it has none (solids, functions, cameras, transforms).
std::optional<std::string> value_key(const Value& value);

}  // namespace hlr::runtime
