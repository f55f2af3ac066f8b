// Functions are values: a user `def` (a closure over the scope it was defined in) or a built-in from a
// registration table (builtins.hpp). Both are called through the same argument binder (arguments.hpp).
#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "lang/ast.hpp"
#include "runtime/values/value.hpp"

namespace hlr::runtime {

class CallArgs;
class Scope;
struct Param;

using BuiltinImpl = Value (*)(CallArgs& args);

struct BuiltinFunction {
  BuiltinImpl impl = nullptr;
  std::string signature;  // shown in hints: "box(sx, sy, sz) | box(min: p, max: q) | box(size: v, center: p)"
  std::string summary;    // one sentence for :help and the reference
  // The parameter lists the implementation binds (one per form, the form the arguments choose); the
  // resolver checks calls against them before the first frame. Empty: any arguments (min, max).
  std::vector<const std::vector<Param>*> forms;
};

struct UserFunction {
  const lang::DefStmt* def = nullptr;  // points into a Script the SourceTable keeps alive
  std::shared_ptr<Scope> closure;      // the scope the `def` ran in: lexical scoping, recursion
};

struct Function {
  std::string name;
  std::variant<BuiltinFunction, UserFunction> body;

  bool is_builtin() const { return std::holds_alternative<BuiltinFunction>(body); }
};

}  // namespace hlr::runtime
