// What one run of a script is asked to do — the command line's options that reach the run, also what the
// REPL's :render and a script on standard input pass — and the exit statuses a run reports
// (runtime/LANGUAGE_SPEC.md, "CLI and exit codes").
#pragma once

#include <optional>
#include <string>

#include "core/device/page/hidden_style.hpp"
#include "runtime/base/file_access.hpp"
#include "runtime/base/limits.hpp"
#include "runtime/pipeline/frame_selection.hpp"
#include "runtime/pipeline/output_plan.hpp"

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

struct RunOptions {
  std::string script;                 // the script's path (run_script)
  bool check = false;                 // `hlrscript check`: evaluate every frame, render and write nothing
  bool list_cameras = false;          // --list-cameras FILE: a check printing the cameras of frame 0
  std::optional<std::string> title;   // the captions' and metadata's name (the REPL's); else the script's
  std::optional<std::string> output;  // -o
  std::optional<std::string> camera;
  std::optional<FrameList> frames;
  std::optional<Shard> shard;
  std::optional<HiddenStyle> hidden;  // --hidden off|dashed or --levels N; else the script's style
  unsigned jobs = 0;                  // --jobs: threads for frames and the work inside them; 0: one per core
  bool stats = false;
  bool keep_going = false;  // --keep-going: render the other frames when one fails
  bool verbose = false;     // --verbose: also the notes on what the script asked to accept
  AccessOptions access;     // --allow-path, --out-dir
  Limits limits;            // --limit NAME=N, --frame-timeout
  DeviceOptions device;     // --paper, --margin, --scale, --dpi, --plotter, --pen-order, ...
  bool progress = false;    // a progress line on stderr (set by run_cli: a terminal, and not --quiet)
  bool from_repl = false;   // the REPL's :render: a Ctrl-C stop is the REPL's to report (RenderCancelled)
};

}  // namespace hlr::runtime
