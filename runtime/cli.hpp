// The hlrscript command (runtime/LANGUAGE_SPEC.md, "CLI and exit codes"). run_cli() is main() without
// the process: it writes to the given streams and returns the exit status, so tests can drive it.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "runtime/frame_selection.hpp"
#include "runtime/output_plan.hpp"

namespace hlr::runtime {

enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 64,
  kExitScript = 65,
  kExitInput = 66,
  kExitInternal = 70,
  kExitOutput = 73,
};

struct CliOptions {
  enum class Mode { Render, Check, Demo, Help, Version } mode = Mode::Render;
  std::string script;
  std::optional<std::string> output;  // -o
  std::optional<std::string> camera;
  std::optional<FrameRange> frames;
  std::optional<Shard> shard;
  std::optional<bool> hidden;
  unsigned jobs = 0;  // --jobs: threads for frames and the work inside them; 0: one per core
  bool stats = false;
  DeviceOptions device;  // --paper, --margin, --scale, --dpi, --plotter, --pen-order, ...
  int demo_frames = 12;  // --demo --frames N
};

// Parses the command line (Boost.Program_options). Returns nullopt after writing a usage error to `err`.
std::optional<CliOptions> parse_cli(int argc, const char* const argv[], std::ostream& err);
std::string usage_text();

int run_cli(int argc, const char* const argv[], std::ostream& out, std::ostream& err);

}  // namespace hlr::runtime
