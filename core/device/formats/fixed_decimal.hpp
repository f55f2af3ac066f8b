// Coordinates in the vector files' text: fixed point, as std::to_chars writes it, a few times faster.
#pragma once

#include <string>

namespace hlr {

// Appends `v` with `decimals` digits after the point as std::to_chars(…, chars_format::fixed, decimals)
// writes it (the exact value rounded to the nearest, ties to even), then drops trailing zeros and a bare
// point, and writes "-0" as "0": 12.5, 0.125, -3, 0.
void append_fixed(std::string& out, double v, int decimals);

}  // namespace hlr
