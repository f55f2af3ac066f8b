// The hlrscript command: the options, then the mode they ask for — help, version, the plotter list, the
// demo, watch, the REPL, or a script's render or check (runtime/pipeline/script_run.hpp). What escapes a
// mode becomes an exit status here.
#include "runtime/cli/cli.hpp"

#include <chrono>
#include <csignal>
#include <ostream>
#include <sstream>

#include "core/device/page/atomic_file.hpp"
#include "core/device/plotters/gcode_profile.hpp"
#include "core/device/plotters/hpgl_profile.hpp"
#include "runtime/base/did_you_mean.hpp"
#include "runtime/base/file_access.hpp"
#include "runtime/base/interrupt.hpp"
#include "runtime/builtins/help_text.hpp"
#include "runtime/cli/demo_script.hpp"
#include "runtime/eval/program.hpp"
#include "runtime/pipeline/script_run.hpp"
#include "runtime/repl/repl.hpp"

namespace hlr::runtime {

namespace {

constexpr const char* kVersion = "hlrscript 0.1.0";

// The demo is a built-in script (runtime/cli/demo_script.cpp) on the normal path, to carrier.pdf unless -o.
int run_demo(CliOptions o, std::ostream& out, std::ostream& err) {
  const auto start = std::chrono::steady_clock::now();
  const auto program =
      Program::from_text("hlrscript-demo.hls", demo_script(o.demo_frames), "hlrscript-demo.hls", o.access);
  program->set_limits(o.limits);
  if (!program->parsed()) {  // never: the text is ours
    print_diagnostics(err, program->syntax_errors(), program->sources());
    return kExitInternal;
  }
  if (!o.output) o.output = "carrier.pdf";
  o.frames.reset();
  return run_loaded_program(*program, o, out, err, program.get(), start);
}

int print_help(const std::string& topic, std::ostream& out, std::ostream& err) {
  if (topic.empty()) {
    out << usage_text();
    return kExitOk;
  }
  if (topic == "reference") {
    out << builtin_reference();
    return kExitOk;
  }
  if (const std::optional<std::string> text = language_help(topic)) {
    out << *text;
    return kExitOk;
  }
  const std::string guess = did_you_mean(topic, language_help_topics());
  err << "hlrscript: no help on '" << topic << "'" << (guess.empty() ? "" : "; " + guess) << "\n"
      << "hint: hlrscript help NAME for a built-in (box) or a statement (draw); hlrscript help reference "
         "lists them all\n";
  return kExitUsage;
}

}  // namespace

int run_cli(int argc, const char* const argv[], std::ostream& out, std::ostream& err) {
  std::istringstream nothing;
  return run_cli(argc, argv, nothing, false, out, err);
}

int run_cli(int argc, const char* const argv[], std::istream& in, bool in_is_terminal, std::ostream& out,
            std::ostream& err, bool err_is_terminal) {
  std::optional<CliOptions> options = parse_cli(argc, argv, err);
  if (!options) return kExitUsage;
  options->progress = err_is_terminal && !options->quiet;
  try {
    switch (options->mode) {
      case CliOptions::Mode::Help:
        return print_help(options->help_topic, out, err);
      case CliOptions::Mode::ListPlotters:
        for (const HpglProfile& p : builtin_hpgl_profiles()) out << p.name << "\n";
        for (const GcodeProfile& p : builtin_gcode_profiles()) out << p.name << "\n";
        return kExitOk;
      case CliOptions::Mode::Version:
        out << kVersion << "\nlibrary modules: " << stdlib_module_directory().string() << "\n";
        return kExitOk;
      case CliOptions::Mode::Demo: {
        const InterruptHandler signals({SIGINT, SIGTERM});  // a clean stop: RunInterrupted, exit 130
        return run_demo(*options, out, err);
      }
      case CliOptions::Mode::Watch:
        return run_watch(*options, out, err);
      case CliOptions::Mode::Repl:
        return run_repl(*options, options->repl_requested, in, in_is_terminal, out, err);
      case CliOptions::Mode::Render:
      case CliOptions::Mode::Check: {
        const InterruptHandler signals({SIGINT, SIGTERM});
        return run_script(*options, out, err);
      }
    }
  } catch (const DeviceError& e) {
    err << "hlrscript: error: " << e.what() << "\n";
    return kExitOutput;
  } catch (const std::exception& e) {
    err << "hlrscript: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitInternal;
}

}  // namespace hlr::runtime
