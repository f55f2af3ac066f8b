// The check before the first frame (as jlox's resolver): one walk over the whole program — every branch,
// loop body and function body, and the files it includes — that reports
//   - names used where nothing defines them ("unknown name 'bx'", with "did you mean"),
//   - calls of built-ins and of `def`s whose arguments their parameters cannot take (too many, a
//     required one missing, an unknown or repeated name), against the parameter lists the built-in
//     binds (BuiltinFunction::forms) or the def declares,
//   - calls of a built-in constant ("'pi' is a number, not a function"),
// with the same words the evaluator uses, so a mistake reads the same whether found early or late.
//
// Scoping follows the evaluator (runtime/eval/evaluator.hpp): statements run in order, so outside functions a
// name must be defined before it is used; a function body runs when it is called, so it sees every name
// its enclosing scopes define, before or after the `def` (mutual recursion, helpers defined later).
// Values are unknown here: a call through a `let` name or a parameter is not checked, and a built-in
// with several forms is accepted when any form takes the arguments (the implementation picks one by the
// values and checks again).
#pragma once

#include <vector>

#include "lang/diagnostic.hpp"
#include "runtime/base/source_table.hpp"

namespace hlr::runtime {

struct Resolution {
  std::vector<lang::Diagnostic> errors;  // in order of discovery; empty: nothing found
  bool uses_frames = false;              // the program reads `frames` (the sequence's length)
};

// Includes are loaded into `sources` as the evaluator would load them; one that cannot be read or parsed
// is left to the evaluator, which reports it with its context.
Resolution resolve_program(const SourceEntry& main, SourceTable& sources);

}  // namespace hlr::runtime
