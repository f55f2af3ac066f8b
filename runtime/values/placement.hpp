// Solids, groups and (nested) lists of them, flattened into placed solids: what `draw`, `group()` and
// `place()` accept.
#pragma once

#include <string>
#include <vector>

#include "lang/source.hpp"
#include "runtime/values/budget.hpp"
#include "runtime/values/value.hpp"

namespace hlr::runtime {

// True for a solid, a group, or a list whose items all are (checked lazily by flatten_placed).
bool is_drawable(const Value& value);

// The placed solids of `value`, each then moved by `then` (identity when absent). Anything else is an
// error at `span` naming `what` ("draw", "group()") and, inside a list, the offending item's position.
std::vector<PlacedSolid> flatten_placed(const Value& value, const Affine3& then, const lang::SourceSpan& span,
                                        const std::string& what, Budget& budget);

}  // namespace hlr::runtime
