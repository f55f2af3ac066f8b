// Internals shared by the evaluator's source files.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "lang/ast.hpp"
#include "lang/source.hpp"
#include "runtime/base/did_you_mean.hpp"
#include "runtime/base/eval_error.hpp"
#include "runtime/base/limits.hpp"
#include "runtime/values/arguments.hpp"

namespace hlr::runtime {

// Counts the evaluator's native recursion; past kMaxEvalDepth an error, never a stack overflow.
class DepthGuard {
 public:
  DepthGuard(std::size_t& depth, const lang::SourceSpan& span) : depth_(depth) {
    if (++depth_ > kMaxEvalDepth) {
      --depth_;
      fail(span, limit_message("nested evaluations", kMaxEvalDepth),
           "simplify the nesting of calls and blocks");
    }
  }
  ~DepthGuard() { --depth_; }
  DepthGuard(const DepthGuard&) = delete;
  DepthGuard& operator=(const DepthGuard&) = delete;

 private:
  std::size_t& depth_;
};

// "f(a, b = 2)": a user function's signature as written, for hints.
std::string def_signature(const std::string& name, const lang::DefStmt& def, const SourceTable& sources);
// Which argument fills each of the def's parameters; the errors of match_arguments.
std::vector<int> match_def_arguments(const CallSite& site, const std::vector<Arg>& args,
                                     const lang::DefStmt& def);

// A note pointing at `span`, appended to the error's first diagnostic while there are few notes (a deep
// recursion would otherwise list every call).
void add_note(EvalError& error, const lang::SourceSpan& span, const std::string& message);

}  // namespace hlr::runtime
