// The hlrscript command (runtime/LANGUAGE_SPEC.md, "CLI and exit codes"). run_cli() is main() without
// the process: it writes to the given streams and returns the exit status, so tests can drive it.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "runtime/frame_selection.hpp"
#include "runtime/output_plan.hpp"
#include "runtime/program.hpp"

namespace hlr::runtime {

enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 64,
  kExitScript = 65,
  kExitInput = 66,
  kExitInternal = 70,
  kExitOutput = 73,
  kExitDenied = 77,        // a script reached outside what it may read or write (sysexits' EX_NOPERM)
  kExitInterrupted = 130,  // 128 + SIGINT, as shells report it
};

struct CliOptions {
  enum class Mode { Render, Check, Watch, Demo, Repl, Help, Version, ListPlotters } mode = Mode::Render;
  bool list_cameras = false;  // --list-cameras FILE: Check, printing the cameras of frame 0
  std::string script;
  std::optional<std::string> title;   // the captions' and metadata's name (the REPL's); else the script's
  std::string help_topic;             // hlrscript help TOPIC
  std::optional<std::string> output;  // -o
  std::optional<std::string> camera;
  std::optional<FrameList> frames;
  std::optional<Shard> shard;
  std::optional<bool> hidden;
  unsigned jobs = 0;  // --jobs: threads for frames and the work inside them; 0: one per core
  bool stats = false;
  bool keep_going = false;      // --keep-going: render the other frames when one fails
  bool verbose = false;         // --verbose: also the notes on what the script asked to accept
  AccessOptions access;         // --allow-path, --out-dir
  Limits limits;                // --limit NAME=N, --frame-timeout
  DeviceOptions device;         // --paper, --margin, --scale, --dpi, --plotter, --pen-order, ...
  int demo_frames = 12;         // --demo --frames N
  bool repl_requested = false;  // `hlrscript repl` / --repl: a REPL even when stdin is not a terminal
  bool quiet = false;           // --quiet: no progress line
  bool progress = false;        // set by run_cli: a progress line on stderr (a terminal, and not --quiet)
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

// For main(), whose process ends when run_cli returns: a script run then leaves its loaded program (the
// syntax tree, most of the memory of a large generated script) to the kernel instead of freeing it node
// by node — a fifth of a 4 MB script's `check`. The program stays reachable, so leak checkers are quiet.
void leave_program_at_exit();

// `hlrscript FILE` (options.script): load, then run_loaded_program. `inputs`, when given, receives the
// files the run read (the script, its includes, imported meshes) — what watch mode follows.
int run_script(const CliOptions& options, std::ostream& out, std::ostream& err,
               std::vector<std::filesystem::path>* inputs = nullptr);

// A loaded script through the whole run (frame 0, checks, the frame pipeline, reports), as for a file:
// the REPL's :render and scripts read from standard input.
int run_loaded_program(const Program& program, const CliOptions& options, std::ostream& out,
                       std::ostream& err);

// hlrscript watch FILE (runtime/watch.cpp): renders whenever an input changes; never returns.
int run_watch(const CliOptions& options, std::ostream& out, std::ostream& err);

// The REPL (runtime/repl.cpp): a terminal session, a transcript from a pipe when asked for by name, else
// standard input as a script.
int run_repl(const CliOptions& options, std::istream& in, bool in_is_terminal, std::ostream& out,
             std::ostream& err);

}  // namespace hlr::runtime
