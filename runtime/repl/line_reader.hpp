// Where the REPL's lines come from: a terminal with line editing, history and completion (libedit), or
// any stream (a pipe, a test), behind one small interface.
#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hlr::runtime {

class LineReader {
 public:
  virtual ~LineReader() = default;
  // The next line, without its newline; nullopt at the end of input (Ctrl-D).
  virtual std::optional<std::string> read(const std::string& prompt) = 0;
  // Keeps an entry (one statement, however many lines) in the history.
  virtual void remember(const std::string& entry) = 0;
};

// Words to complete the current word with, given the whole line so far.
using Completer = std::function<std::vector<std::string>(const std::string& line, const std::string& word)>;

// Lines from `in`; prompts go to `out` only when `echo_prompt` (a terminal the plain way).
std::unique_ptr<LineReader> make_stream_reader(std::istream& in, std::ostream& out, bool echo_prompt);

// The terminal through libedit: Emacs keys, history kept in `history` (at most 1000 entries, read at
// start, written after every entry), Tab completing with `complete` (file names when it offers none).
std::unique_ptr<LineReader> make_terminal_reader(const std::filesystem::path& history, Completer complete);

// $XDG_STATE_HOME/hlrscript/history, else ~/.local/state/hlrscript/history.
std::filesystem::path default_history_path();

}  // namespace hlr::runtime
