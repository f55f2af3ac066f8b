// The error every camera constructor throws for an invalid parameter. It names the constructor and the
// parameter so the runtime can point at the offending argument (it attaches source positions later):
//   bad argument 'fov' to lookat(): must be between 0 and 180 degrees (got 190)
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

#include "core/format_number.hpp"

namespace hlr {

struct CameraError : std::invalid_argument {
  std::string function;   // constructor name as the script spells it: lookat, ortho, orbit, desens
  std::string parameter;  // argument name as the script spells it: fov, up, rho, ...

  CameraError(std::string function_, std::string parameter_, const std::string& reason)
      : std::invalid_argument("bad argument '" + parameter_ + "' to " + function_ + "(): " + reason),
        function(std::move(function_)),
        parameter(std::move(parameter_)) {}

  // "(got 190)": the offending value as a user would have typed it.
  static std::string got(double value) { return "(got " + format_for_message(value) + ")"; }
};

}  // namespace hlr
