// The hlrscript command (runtime/LANGUAGE_SPEC.md, "CLI and exit codes"). run_cli() is main() without
// the process: it writes to the given streams and returns the exit status, so tests can drive it.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "runtime/pipeline/run_options.hpp"

namespace hlr::runtime {

// The command line's options: what a run is asked to do (RunOptions) and the mode that runs it.
struct CliOptions : RunOptions {
  enum class Mode { Render, Check, Watch, Demo, Repl, Help, Version, ListPlotters } mode = Mode::Render;
  std::string help_topic;       // hlrscript help TOPIC
  int demo_frames = 12;         // --demo --frames N
  bool repl_requested = false;  // `hlrscript repl` / --repl: a REPL even when stdin is not a terminal
  bool quiet = false;           // --quiet: no progress line
};

// Parses the command line (Boost.Program_options). Returns nullopt after writing a usage error to `err`.
std::optional<CliOptions> parse_cli(int argc, const char* const argv[], std::ostream& err);
std::string usage_text();

// `in` is what a script on standard input or the REPL reads; `in_is_terminal` says whether it is a
// terminal (then the REPL reads the terminal itself, through libedit); `err_is_terminal` whether long
// runs show a progress line. The short form reads nothing.
int run_cli(int argc, const char* const argv[], std::istream& in, bool in_is_terminal, std::ostream& out,
            std::ostream& err, bool err_is_terminal = false);
int run_cli(int argc, const char* const argv[], std::ostream& out, std::ostream& err);

// hlrscript watch FILE (watch.cpp): renders whenever an input changes; never returns.
int run_watch(const CliOptions& options, std::ostream& out, std::ostream& err);

}  // namespace hlr::runtime
