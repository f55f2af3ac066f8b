// Numbers in messages, written one way everywhere below the language: what a user would have typed.
// At most six significant digits, trailing zeros dropped ("0.25", "1e-06", "1.23457e+06", as printf's
// %g), except that whole numbers below 1e15 keep all their digits ("1000000", not "1e+06": counts, pen
// numbers and sizes read as written); "nan", "inf", "-inf"; -0 is "0". A value's own text in the
// language (str(), "{x}") is the runtime's format_number, which keeps every digit that reads back.
#pragma once

#include <string>

namespace hlr {

std::string format_for_message(double value);

// A millimetre figure on a sheet, to 0.1 mm (a plotter step is 0.025 mm; finer digits are noise of the
// unit conversion): "284.7", "206", "-1e+300".
std::string format_mm_for_message(double mm);

}  // namespace hlr
