#include "runtime/repl/line_reader.hpp"

// libedit's readline emulation (BSD licence); its header needs <cstdio> first.
#include <editline/readline.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <istream>
#include <ostream>
#include <system_error>

namespace hlr::runtime {

namespace {

class StreamReader : public LineReader {
 public:
  StreamReader(std::istream& in, std::ostream& out, bool echo) : in_(in), out_(out), echo_(echo) {}
  std::optional<std::string> read(const std::string& prompt) override {
    if (echo_) out_ << prompt << std::flush;
    std::string line;
    if (!std::getline(in_, line)) return std::nullopt;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return line;
  }
  void remember(const std::string&) override {}

 private:
  std::istream& in_;
  std::ostream& out_;
  bool echo_;
};

// libedit calls plain functions: the one terminal reader of the process keeps its completer here.
Completer* active_completer = nullptr;
std::vector<std::string> pending_matches;

char* next_match(const char*, int state) {
  if (state == 0) std::reverse(pending_matches.begin(), pending_matches.end());
  if (pending_matches.empty()) return nullptr;
  char* m = ::strdup(pending_matches.back().c_str());
  pending_matches.pop_back();
  return m;
}

char** complete(const char* text, int, int end) {
  if (!active_completer) return nullptr;
  // The line up to the cursor: what the word is completed in (a call's parentheses, a :command).
  const std::string line = rl_line_buffer ? rl_line_buffer : "";
  pending_matches = (*active_completer)(
      line.substr(0, std::min(line.size(), static_cast<std::size_t>(std::max(end, 0)))), text);
  if (pending_matches.empty()) return nullptr;  // libedit then completes file names
  return rl_completion_matches(text, next_match);
}

class TerminalReader : public LineReader {
 public:
  TerminalReader(std::filesystem::path history, Completer completer)
      : history_(std::move(history)), completer_(std::move(completer)) {
    using_history();
    stifle_history(1000);
    std::error_code ec;
    std::filesystem::create_directories(history_.parent_path(), ec);
    read_history(history_.c_str());
    active_completer = &completer_;
    rl_attempted_completion_function = complete;
  }
  ~TerminalReader() override {
    active_completer = nullptr;
    rl_attempted_completion_function = nullptr;
  }
  std::optional<std::string> read(const std::string& prompt) override {
    char* line = readline(prompt.c_str());
    if (!line) return std::nullopt;
    std::string out(line);
    std::free(line);
    return out;
  }
  void remember(const std::string& entry) override {
    if (entry.empty()) return;
    add_history(entry.c_str());
    write_history(history_.c_str());
  }

 private:
  std::filesystem::path history_;
  Completer completer_;
};

}  // namespace

std::unique_ptr<LineReader> make_stream_reader(std::istream& in, std::ostream& out, bool echo_prompt) {
  return std::make_unique<StreamReader>(in, out, echo_prompt);
}

std::unique_ptr<LineReader> make_terminal_reader(const std::filesystem::path& history, Completer complete) {
  return std::make_unique<TerminalReader>(history, std::move(complete));
}

std::filesystem::path default_history_path() {
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state)
    return std::filesystem::path(state) / "hlrscript" / "history";
  const char* home = std::getenv("HOME");
  return std::filesystem::path(home && *home ? home : ".") / ".local" / "state" / "hlrscript" / "history";
}

}  // namespace hlr::runtime
