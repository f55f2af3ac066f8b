// A failure that is not at a place in the script: no camera declared, an unknown --camera name, a bad
// -o pattern. Carries the hint and the exit status the command reports.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace hlr::runtime {

struct RunError : std::runtime_error {
  RunError(const std::string& message, std::string hint_, int exit_code_)
      : std::runtime_error(message), hint(std::move(hint_)), exit_code(exit_code_) {}
  std::string hint;
  int exit_code;
};

}  // namespace hlr::runtime
