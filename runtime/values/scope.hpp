// Lexical scopes. Each block, call and loop iteration opens a scope whose parent is where it sits in the
// source (for a call: the function's closure), so a name means what it meant where it was written.
//
// Closures and cycles: `def f` stores f in the scope that f's closure points to, a reference cycle by
// design (it is what makes recursion work). The evaluator remembers every scope a `def` ran in and
// clears them when the evaluation ends (Evaluator::~Evaluator), which breaks every such cycle.
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "lang/source.hpp"
#include "runtime/values/value.hpp"

namespace hlr::runtime {

struct Binding {
  Value value;
  lang::SourceSpan span;  // where the name was defined
};

class Scope {
 public:
  explicit Scope(std::shared_ptr<Scope> parent = nullptr) : parent_(std::move(parent)) {}

  // This scope, then its parents.
  const Binding* find(const std::string& name) const {
    for (const Scope* s = this; s; s = s->parent_.get()) {
      const auto it = s->names_.find(name);
      if (it != s->names_.end()) return &it->second;
    }
    return nullptr;
  }
  const Binding* find_local(const std::string& name) const {
    const auto it = names_.find(name);
    return it == names_.end() ? nullptr : &it->second;
  }
  void define(const std::string& name, Value value, const lang::SourceSpan& span) {
    names_.insert_or_assign(name, Binding{std::move(value), span});
  }
  // Every name visible from here (for "did you mean" hints).
  std::vector<std::string> visible_names() const {
    std::vector<std::string> out;
    for (const Scope* s = this; s; s = s->parent_.get())
      for (const auto& entry : s->names_) out.push_back(entry.first);
    return out;
  }
  void clear() { names_.clear(); }

 private:
  std::shared_ptr<Scope> parent_;
  std::unordered_map<std::string, Binding> names_;
};

using ScopePtr = std::shared_ptr<Scope>;

}  // namespace hlr::runtime
