// The pieces of JSON text the JSON device writes, appended straight to a string: numbers as the
// shortest text that reads back to the same double (std::to_chars), integers, and strings escaped as
// RFC 8259 asks. No document tree is built, so a frame's text costs about what its bytes do.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace hlr {

// The shortest decimal that reads back to `v`, with ".0" added to whole numbers so that a reader keeps
// them floating (2 → "2.0"; 1e+20 and 0.1 as they are). `v` must be finite.
void append_json_number(std::string& out, double v);

void append_json_integer(std::string& out, long long v);

// `s` quoted, with '"', '\\' and control characters escaped; false (and `out` unspecified) when `s` is
// not well-formed UTF-8.
bool append_json_string(std::string& out, std::string_view s);

}  // namespace hlr
