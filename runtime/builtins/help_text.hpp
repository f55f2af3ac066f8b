// Help on the language, from the tables the evaluator runs on: the built-ins' registration rows
// (signature, summary, the parameter lists they bind) and the statements' forms. The REPL's `:help
// TOPIC`, `hlrscript help TOPIC` and runtime/BUILTINS.md (`hlrscript help reference`) all print these.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace hlr::runtime {

// Help on a built-in ("box") or a statement keyword ("draw"); nullopt for anything else.
std::optional<std::string> language_help(const std::string& topic);

// The topics language_help knows, for completion and "did you mean".
std::vector<std::string> language_help_topics();

// Every built-in, grouped as the registration tables are, in Markdown (runtime/BUILTINS.md).
std::string builtin_reference();

// The parameter names `function`'s forms accept (completion after "lookat("); empty when unknown.
std::vector<std::string> builtin_parameter_names(const std::string& function);

}  // namespace hlr::runtime
