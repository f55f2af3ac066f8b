// Built-in functions and constants. Each module (builtins_*.cpp) ends with a registration table of
// {name, signature, implementation} rows (Lua's luaL_Reg) and a register_* function that adds them;
// adding a built-in is one function and one row. Built-ins are looked up after every scope, so a script
// may shadow any of them with its own `let` or `def`.
#pragma once

#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/camera/camera_error.hpp"
#include "runtime/values/arguments.hpp"
#include "runtime/values/function.hpp"
#include "runtime/values/value.hpp"

namespace hlr::runtime {

struct BuiltinEntry {
  const char* name;
  const char* signature;  // every accepted form, shown in hints
  BuiltinImpl impl;
  const char* summary;                  // what it gives, one sentence (:help, runtime/BUILTINS.md)
  std::vector<const ParamList*> forms;  // the lists `impl` binds; empty only for variadic built-ins
};

class BuiltinTable {
 public:
  void add(const BuiltinEntry& entry);
  template <std::size_t N>
  void add_all(const BuiltinEntry (&entries)[N]) {
    for (const BuiltinEntry& e : entries) add(e);
  }
  void add_constant(const std::string& name, Value value);

  const Value* find(const std::string& name) const;
  std::vector<std::string> names() const;  // sorted

 private:
  std::unordered_map<std::string, Value> entries_;
};

// Every module's built-ins, registered once.
const BuiltinTable& builtins();

void register_math_builtins(BuiltinTable& table);       // builtins_math.cpp
void register_core_builtins(BuiltinTable& table);       // builtins_core.cpp: len, range, str, group, place
void register_vector_builtins(BuiltinTable& table);     // builtins_vectors.cpp: vectors and 2-D outlines
void register_transform_builtins(BuiltinTable& table);  // builtins_transforms.cpp
void register_solid_builtins(BuiltinTable& table);      // builtins_solids.cpp
void register_shape_builtins(BuiltinTable& table);      // builtins_shapes.cpp: pyramid, platonic, cone, ...

void register_camera_builtins(BuiltinTable& table);
void register_animation_builtins(BuiltinTable& table);  // builtins_animation.cpp: ease, track, spline, follow
void register_hatch_builtins(BuiltinTable& table);      // builtins_hatch.cpp: hatch
void register_boolean_builtins(
    BuiltinTable& table);                            // builtins_booleans.cpp: union, difference, intersection
void register_import_builtins(BuiltinTable& table);  // builtins_import.cpp: import  // builtins_cameras.cpp

// ---- helpers shared by the modules ------------------------------------------------------------------

// A built-in's numeric result; a NaN or infinity is an error at the call: "sqrt(-1) is not a real number",
// "pow(10, 400) overflows".
Value finite_number(const CallArgs& call, double x);
Value finite_vector(const CallArgs& call, Vector3 v);

// A solid made by a generator, named after it ("box"). `faces` (an upper bound, known from the
// arguments) is charged to the frame's budget before anything is built, so sphere(1, slices: 1e6) is a
// limit error, not an exhausted memory. The generator's invalid_argument or runtime_error becomes an
// error at the call.
// The optional `crease:` parameter of the tessellated generators, and its check: degrees from 0 to 180,
// else an error at the argument.
Param crease_param(double fallback = 30);
double crease_angle(const Bound& b, std::size_t i);
// The optional `contours:` parameter of the curved generators and import: "edges" (the default: the
// outline is made of the mesh's edges) or "smooth" (the interpolated contour of the smooth surface the mesh
// stands for, Solid::smooth_contours); anything else is an error at the argument.
Param contours_param();
bool smooth_contours(const Bound& b, std::size_t i);
// `solid` marked to be drawn with smooth contours when `smooth`.
Solid with_contours(Solid solid, bool smooth);

// Visits the items of list argument `i` (named `param` in messages), each of which must itself be a list:
// each is bound as a one-argument call so the typed accessors check it (`visit(one, k)` reads it as
// `one`'s argument 0). An item that is not a list fails with "ITEM k is a number, expected EXPECTED".
void for_each_sublist(const CallArgs& call, const Bound& b, std::size_t i, std::string_view param,
                      const std::string& item, const std::string& expected,
                      const std::function<void(const Bound& one, std::size_t k)>& visit);

// The solids of `value` (a solid, group or list), each moved to where it is placed and given back with the
// identity: the process's cached copy for a placement seen before (SolidCache::placed). What hatch() and the
// booleans work on, in the coordinates of the value given; anything else is flatten_placed's error at `span`.
std::vector<PlacedSolid> solids_where_placed(const CallArgs& call, const Value& value,
                                             const lang::SourceSpan& span);

Value generated_solid(const CallArgs& call, std::size_t faces, const std::function<Solid()>& make);

// A camera built by `make`; a CameraError goes to the argument it names (core's names, or their script
// aliases object and observer), else to the call. Shared by the camera and timeline built-ins.
template <typename Make>
Value make_camera(const Bound& b, const ParamList& params, Make&& make) {
  try {
    return Value::camera(make());
  } catch (const CameraError& e) {
    std::string name = e.parameter;
    if (name == "object_position") name = "object";
    if (name == "observer_position") name = "observer";
    for (std::size_t i = 0; i < params.size(); ++i)
      if (params[i].name == name) b.call().fail(b.span(i), e.what());
    b.call().fail_call(e.what());
  }
}

}  // namespace hlr::runtime
