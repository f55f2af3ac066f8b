// The REPL's loop: lines from the terminal (libedit) or a pipe into a ReplSession, replies out. When
// standard input is not a terminal and no REPL was asked for by name, it is a script (`<stdin>`).
#include "runtime/repl/repl.hpp"

#include <signal.h>
#include <unistd.h>

#include <istream>
#include <ostream>
#include <sstream>

#include "runtime/base/interrupt.hpp"
#include "runtime/base/source_table.hpp"
#include "runtime/eval/program.hpp"
#include "runtime/pipeline/script_run.hpp"
#include "runtime/repl/line_reader.hpp"
#include "runtime/repl/repl_session.hpp"

namespace hlr::runtime {

namespace {

int run_stdin_script(const RunOptions& o, std::istream& in, std::ostream& out, std::ostream& err) {
  const InterruptHandler signals(
      {SIGINT, SIGTERM});  // a clean stop, as for a script named on the command line
  std::ostringstream text;
  text << in.rdbuf();
  const auto program =
      Program::from_text("<stdin>", text.str(), std::filesystem::current_path() / "stdin.hls", o.access);
  program->set_limits(o.limits);
  if (!program->parsed()) {
    print_diagnostics(err, program->syntax_errors(), program->sources());
    return kExitScript;
  }
  return run_loaded_program(*program, o, out, err);  // a script run, reported as one (not the REPL's)
}

}  // namespace

int run_repl(const RunOptions& o, bool asked_by_name, std::istream& in, bool terminal, std::ostream& out,
             std::ostream& err) {
  if (!terminal && !asked_by_name) return run_stdin_script(o, in, out, err);

  ReplSession session(terminal_size(STDOUT_FILENO));
  session.set_run_options(o.access, o.limits);
  // Asked once, before line editing owns the terminal: the answer does not change within a session.
  const TerminalGraphics graphics =
      terminal ? detect_terminal_graphics(STDIN_FILENO, STDOUT_FILENO) : TerminalGraphics::Braille;
  const auto fit_terminal = [&] {
    const TerminalSize size = terminal_size(STDOUT_FILENO);
    session.set_terminal_size(size);
    session.set_graphics(graphics, terminal_pixels(STDOUT_FILENO, size.columns, size.rows));
  };
  fit_terminal();
  if (!o.script.empty()) out << session.feed(":load " + o.script).text;
  std::unique_ptr<LineReader> reader =
      terminal ? make_terminal_reader(default_history_path(),
                                      [&](const std::string& line, const std::string& word) {
                                        return session.completions(line, word);
                                      })
               : make_stream_reader(in, out, false);
  if (terminal)
    out << "hlrscript 0.1.0 REPL: statements as in a script, :help for commands, :quit or Ctrl-D to leave\n";
  // Ctrl-C cancels the line being typed, or stops the work under way, instead of ending the session.
  const InterruptHandler ctrl_c({SIGINT});
  std::string entry;
  for (;;) {
    interrupt_requested() = false;
    const std::optional<std::string> line = reader->read(session.continuing() ? "...> " : "hls> ");
    if (!line) {
      if (interrupt_requested() && terminal) {  // Ctrl-C: drop what was typed, stay
        session.cancel_input();
        entry.clear();
        out << "\n";
        continue;
      }
      if (terminal) out << "\n";
      break;
    }
    entry += *line + "\n";
    fit_terminal();
    interrupt_requested() = false;  // a Ctrl-C typed while reading the line is no request to stop
    const ReplReply reply = session.feed(*line);
    if (reply.kind == ReplReply::Kind::More) continue;
    reader->remember(entry.substr(0, entry.size() - 1));
    entry.clear();
    out << reply.text << std::flush;
    if (reply.kind == ReplReply::Kind::Quit) break;
  }
  (void)err;
  return kExitOk;
}

}  // namespace hlr::runtime
