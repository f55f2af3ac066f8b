// One run of a script, from its file or already loaded, to its files and its report: frame 0 (animation
// length, cameras, output names), the checks before rendering, the frame pipeline, then what was written
// or what failed. Errors become exit statuses here (and usage errors in runtime/cli/), nowhere else.
#pragma once

#include <chrono>
#include <filesystem>
#include <iosfwd>
#include <vector>

#include "runtime/eval/program.hpp"
#include "runtime/pipeline/run_options.hpp"

namespace hlr::runtime {

// `hlrscript FILE` (options.script): load, then run_loaded_program. `inputs`, when given, receives the
// files the run read (the script, its includes, imported meshes) — what watch mode follows.
int run_script(const RunOptions& options, std::ostream& out, std::ostream& err,
               std::vector<std::filesystem::path>* inputs = nullptr);

// A loaded script through the whole run (frame 0, checks, the frame pipeline, reports), as for a file:
// the demo, the REPL's :render and scripts read from standard input. `releasable` is the same program
// when nothing else will evaluate it: a run of frame 0 alone then frees its syntax tree before the hidden
// lines (Program::release_syntax). `start` is when the run began, for the time it reports.
int run_loaded_program(const Program& program, const RunOptions& options, std::ostream& out,
                       std::ostream& err, Program* releasable = nullptr,
                       std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now());

// For main(), whose process ends when run_cli returns: a script run then leaves its loaded program (the
// syntax tree, most of the memory of a large generated script) to the kernel instead of freeing it node
// by node — a fifth of a 4 MB script's `check`. The program stays reachable, so leak checkers are quiet.
void leave_program_at_exit();

}  // namespace hlr::runtime
