// Values as text: str(x), string interpolation "{x}" and "{x:fmt}".
// Numbers print with the fewest digits that read back to the same double, positional from 1e-6 to 1e21
// (`1`, `0.5`, `100000`), scientific outside (`1e-07`, `1e+21`). That is a value's text in the language;
// numbers quoted in messages go through hlr::format_for_message (core/format_number.hpp).
// Format specs (LANGUAGE_SPEC.md, "Strings"): [0][width][.precision][type], type one of
//   f fixed   e scientific   g (or none, with a precision) significant digits   d whole number   x hex
// `03` pads a number with zeros to width 3, `8.2f` right-aligns in 8 columns, `.3` keeps 3 significant
// digits. A vector or list applies the format to each number inside; a string or bool is padded on the
// right to the width.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "runtime/values/value.hpp"

namespace hlr::runtime {

// A malformed spec or a value it does not fit ("x" of 2.5); the message says which.
struct FormatError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

std::string format_number(double x);

// The text of any value, as str() gives it. Output beyond `max_length` bytes throws FormatError.
std::string display(const Value& value, std::size_t max_length);

// The text of `value` under `spec`; throws FormatError.
std::string format_value(const Value& value, std::string_view spec, std::size_t max_length);

}  // namespace hlr::runtime
