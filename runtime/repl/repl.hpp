// The REPL (repl.cpp): a terminal session, a transcript from a pipe when asked for by name
// (`asked_by_name`: `hlrscript repl`, --repl), else standard input as a script. options.script, when
// given, is loaded first.
#pragma once

#include <iosfwd>

#include "runtime/pipeline/run_options.hpp"

namespace hlr::runtime {

int run_repl(const RunOptions& options, bool asked_by_name, std::istream& in, bool in_is_terminal,
             std::ostream& out, std::ostream& err);

}  // namespace hlr::runtime
