// A fast path of the parser for generated scripts: one solid item in its plainest form, read by hand.
// grammar.hpp (plain_solid_item) says which forms and why.
#pragma once

#include <cstddef>

#include "lang/solid_body.hpp"

namespace hlr::lang {

// Reads the item that starts at `at` (the text runs to `end`; `base` is the start of the file, for the
// items' offsets) into `body` and returns its length in bytes — or returns 0 and leaves `body` as it
// was when the text there is anything but a plain item: another form, or a mistake, which the grammar
// then reads and reports.
std::size_t read_plain_solid_item(const char* base, const char* at, const char* end, SolidBody& body);

}  // namespace hlr::lang
