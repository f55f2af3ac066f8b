// The one error type of evaluation: diagnostics with spans (usually one), and what kind of failure it is
// so the CLI can pick the exit status. Nothing below the CLI prints or exits; errors travel as this.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "lang/diagnostic.hpp"

namespace hlr::runtime {

enum class ErrorKind {
  Script,  // the script is wrong: syntax, evaluation, geometry (exit 65)
  Input,   // a file it names cannot be read (exit 66)
  Denied,  // a file it names is outside what a script may touch (exit 77; file_access.hpp)
};

class EvalError : public std::runtime_error {
 public:
  EvalError(lang::Diagnostic diagnostic, ErrorKind kind = ErrorKind::Script)
      : std::runtime_error(diagnostic.message), kind(kind) {
    diagnostics.push_back(std::move(diagnostic));
  }
  EvalError(std::vector<lang::Diagnostic> all, ErrorKind kind, const std::string& summary)
      : std::runtime_error(summary), diagnostics(std::move(all)), kind(kind) {}

  std::vector<lang::Diagnostic> diagnostics;  // may be empty for a file that cannot be read at all
  ErrorKind kind;
};

[[noreturn]] inline void fail(const lang::SourceSpan& span, std::string message, std::string hint = {}) {
  lang::Diagnostic d;
  d.span = span;
  d.message = std::move(message);
  d.hint = std::move(hint);
  throw EvalError(std::move(d));
}

}  // namespace hlr::runtime
